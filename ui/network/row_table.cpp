#include "ui/network/row_table.hpp"

#include <QHeaderView>
#include <QSignalBlocker>

namespace plumb::ui::row_table {

QTableWidgetItem* cell(const QString& text) {
  auto* item = new QTableWidgetItem(text);
  item->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled);
  return item;
}

void setUp(QTableWidget& table) {
  table.setSelectionBehavior(QAbstractItemView::SelectRows);
  table.setSelectionMode(QAbstractItemView::SingleSelection);
  table.verticalHeader()->hide();
  table.horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
}

int selectedRow(const QTableWidget& table) {
  const auto rows = table.selectionModel() ? table.selectionModel()->selectedRows() : QModelIndexList{};
  return rows.isEmpty() ? -1 : rows.first().row();
}

void selectQuietly(QTableWidget& table, int row) {
  const QSignalBlocker block(&table);
  if (row < 0) table.clearSelection();
  else table.selectRow(row);
}

}  // namespace plumb::ui::row_table

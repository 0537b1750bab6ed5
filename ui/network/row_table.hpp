#pragma once
// What the network's station and link tables share: read-only cells, one selected row at a
// time, and selecting a row from the plan view without echoing the selection back.
#include <QTableWidget>

namespace plumb::ui::row_table {

/// A read-only, selectable cell.
QTableWidgetItem* cell(const QString& text);
/// Whole-row single selection, no row numbers, columns sized to their contents.
void setUp(QTableWidget& table);
/// The selected row, -1 when none.
int selectedRow(const QTableWidget& table);
/// Selects `row` (-1: none) without emitting the table's signals.
void selectQuietly(QTableWidget& table, int row);

}  // namespace plumb::ui::row_table

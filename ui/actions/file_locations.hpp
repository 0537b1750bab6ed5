#pragma once
// Where the file dialogs start and what they propose (issue 17: dialogs forgot the last folder,
// and the export proposed the input's own name). The last folder of each kind is kept in the
// application's settings ("folders/data", "folders/export", "folders/project").
#include <QString>

namespace plumb::ui {

/// Folders remembered separately: where data is read from is rarely where results go.
enum class FolderKind { Data, Export, Project };

/// The folder last chosen for `kind`; empty when none was (or it no longer exists).
QString lastFolder(FolderKind kind);
/// Remembers the folder of `chosen_file` for `kind`.
void rememberFolder(FolderKind kind, const QString& chosen_file);
/// `name` in the last folder of `kind`, else in `fallback_dir`, else `name` alone. A `name`
/// that already has a folder is returned as it is.
QString proposedPath(FolderKind kind, const QString& name, const QString& fallback_dir = {});
/// "<stem>_<suffix>.<extension>" for data read from `source` ("<layer_name>_..." when it has no
/// file): an export never proposes the input's own name.
QString derivedFileName(const QString& source, const QString& layer_name, const QString& suffix,
                        const QString& extension);

}  // namespace plumb::ui

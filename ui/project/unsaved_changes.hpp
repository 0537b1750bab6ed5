#pragma once
// Closing the window with unsaved work (issue 17: quitting never asked). Work is unsaved when
// the undo history is not at its clean point: a registration or manual transform applied since
// the project was last saved or opened. The data files themselves never change in Plumb, so
// loading files alone leaves nothing unsaved.
namespace plumb::ui {

struct AppContext;

/// True when the window may close: nothing unsaved, or the user chose Save (and it was saved)
/// or Discard in the "unsavedChanges" message box; false for Cancel (or a failed save).
bool confirmClose(AppContext& app);

}  // namespace plumb::ui

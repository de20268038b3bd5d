// Dear ImGui widgets generated from parameter tables (core/params.hpp): one widget per row,
// chosen by the row's kind and limits (a slider over the row's range with its unit, a combo
// of its names, a colour editor for an sRGB colour, a checkbox, a text field), its help as the
// tooltip. No option has a widget of its own: a new row in a table shows up in the viewer.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "core/params.hpp"

namespace sansui::viewer {

/// What the user did to one row's widget this frame.
struct WidgetEdit {
  bool changed = false;  ///< `value` is the new value
  bool reset = false;    ///< an optional row was set back to unset (derived)
  params::Value value;
};

/// Draws the widget of `row`. `value` is the row's value; for an optional row left unset the
/// widget shows `derived` (what the scene derives for it) and marks it "derived"; a set optional
/// row is marked "set" with a button that resets it.
WidgetEdit param_widget(const params::ParamInfo& row, const params::Value& value, const params::Value& derived);

/// One changed row: its key and the new value (monostate: reset to unset).
struct RowEdit {
  std::string key;
  params::Value value;
};

/// The widgets of the rows of `table` that `show` accepts; values of `object`, derived values
/// of optional rows from `derived`. Edits are returned, not applied: the caller applies them
/// the way a script step would (Viewer::set_value).
template <class S>
std::vector<RowEdit> table_widgets(const params::Table<S>& table, const S& object, const S& derived,
                                   const std::function<bool(const params::Param<S>&)>& show) {
  std::vector<RowEdit> edits;
  for (const params::Param<S>& row : table.rows) {
    if (!row.exposed || !row.get || !show(row)) continue;
    const WidgetEdit edit = param_widget(row, row.get(object), row.get(derived));
    if (edit.changed || edit.reset) edits.push_back({row.key, edit.reset ? params::Value{} : edit.value});
  }
  return edits;
}

}  // namespace sansui::viewer

#include "viewer/param_widgets.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <variant>

#include <imgui.h>
#include <imgui_stdlib.h>

namespace sansui::viewer {
namespace {

// Integers over a span wider than this get a drag field instead of a slider.
constexpr double max_slider_span = 1e6;

bool is_colour(const params::ParamInfo& row) {
  const params::Limits& l = row.limits;
  return row.kind == params::Kind::reals && l.min_count == 3 && l.max_count == 3 && l.min == 0.0 && l.max == 1.0 && !l.whole;
}

/// The number format of a slider: three significant digits and the unit.
std::string number_format(const params::ParamInfo& row, bool whole) {
  std::string format = whole ? "%lld" : "%.4g";
  if (!row.unit.empty()) format += " " + row.unit;
  return format;
}

bool bounded(const params::Limits& limits) {
  return limits.min && limits.max && std::isfinite(*limits.min) && std::isfinite(*limits.max);
}

bool real_widget(const params::ParamInfo& row, double& v) {
  const std::string format = number_format(row, false);
  if (bounded(row.limits)) {
    double low = *row.limits.min, high = *row.limits.max;
    return ImGui::SliderScalar("##v", ImGuiDataType_Double, &v, &low, &high, format.c_str());
  }
  // Unbounded: a drag whose speed follows the value's size.
  const float speed = static_cast<float>(std::max(std::abs(v) * 0.005, 0.001));
  double low = row.limits.min.value_or(-std::numeric_limits<double>::max());
  double high = row.limits.max.value_or(std::numeric_limits<double>::max());
  return ImGui::DragScalar("##v", ImGuiDataType_Double, &v, speed, &low, &high, format.c_str());
}

bool integer_widget(const params::ParamInfo& row, std::int64_t& v) {
  const std::string format = number_format(row, true);
  const params::Limits& l = row.limits;
  if (bounded(l) && *l.max - *l.min <= max_slider_span) {
    auto low = static_cast<std::int64_t>(std::ceil(*l.min)), high = static_cast<std::int64_t>(std::floor(*l.max));
    return ImGui::SliderScalar("##v", ImGuiDataType_S64, &v, &low, &high, format.c_str());
  }
  std::int64_t low = l.min ? static_cast<std::int64_t>(std::ceil(*l.min)) : std::numeric_limits<std::int64_t>::min() / 2;
  std::int64_t high = l.max ? static_cast<std::int64_t>(std::floor(*l.max)) : std::numeric_limits<std::int64_t>::max() / 2;
  return ImGui::DragScalar("##v", ImGuiDataType_S64, &v, 1.0f, &low, &high, format.c_str());
}

bool choice_widget(const params::ParamInfo& row, std::string& v) {
  bool changed = false;
  if (ImGui::BeginCombo("##v", v.c_str())) {
    for (const std::string& name : row.limits.choices) {
      const bool selected = name == v;
      if (ImGui::Selectable(name.c_str(), selected)) {
        changed = name != v;
        v = name;
      }
      if (selected) ImGui::SetItemDefaultFocus();
    }
    ImGui::EndCombo();
  }
  return changed;
}

bool reals_widget(const params::ParamInfo& row, std::vector<double>& v) {
  if (is_colour(row) && v.size() == 3) {
    float rgb[3] = {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
    if (!ImGui::ColorEdit3("##v", rgb, ImGuiColorEditFlags_Float)) return false;
    v = {rgb[0], rgb[1], rgb[2]};
    return true;
  }
  if (row.limits.min_count == row.limits.max_count && v.size() == row.limits.min_count && v.size() <= 4) {
    const std::string format = number_format(row, false);
    return ImGui::InputScalarN("##v", ImGuiDataType_Double, v.data(), static_cast<int>(v.size()), nullptr, nullptr, format.c_str(),
                               ImGuiInputTextFlags_EnterReturnsTrue);
  }
  // A list of any length: edited as text, "1,2,3".
  std::string text = params::format_value(v);
  if (!ImGui::InputText("##v", &text, ImGuiInputTextFlags_EnterReturnsTrue)) return false;
  try {
    v = std::get<std::vector<double>>(params::parse_text(row, text, row.key));
  } catch (const std::exception&) {
    return false;  // the field keeps the old value; nothing is applied
  }
  return true;
}

/// The row's editor for `v` (a copy the user may change). Returns whether it changed.
bool value_widget(const params::ParamInfo& row, params::Value& v) {
  switch (row.kind) {
    case params::Kind::flag:
      if (!std::holds_alternative<bool>(v)) v = false;
      return ImGui::Checkbox("##v", &std::get<bool>(v));
    case params::Kind::integer:
      if (!std::holds_alternative<std::int64_t>(v)) v = std::int64_t{static_cast<std::int64_t>(row.limits.min.value_or(0.0))};
      return integer_widget(row, std::get<std::int64_t>(v));
    case params::Kind::real:
      if (!std::holds_alternative<double>(v)) v = row.limits.min.value_or(0.0);
      return real_widget(row, std::get<double>(v));
    case params::Kind::choice:
      if (!std::holds_alternative<std::string>(v)) v = std::string();
      return choice_widget(row, std::get<std::string>(v));
    case params::Kind::text:
    case params::Kind::path:
      if (!std::holds_alternative<std::string>(v)) v = std::string();
      return ImGui::InputText("##v", &std::get<std::string>(v), ImGuiInputTextFlags_EnterReturnsTrue);
    case params::Kind::reals:
      if (!std::holds_alternative<std::vector<double>>(v)) v = std::vector<double>(row.limits.min_count, row.limits.min.value_or(0.0));
      return reals_widget(row, std::get<std::vector<double>>(v));
  }
  return false;
}

void tooltip(const params::ParamInfo& row) {
  if (!ImGui::IsItemHovered()) return;
  ImGui::BeginTooltip();
  ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
  ImGui::TextUnformatted(row.help.c_str());
  const std::string allowed = params::allowed_text(row);
  if (!allowed.empty()) ImGui::TextDisabled("allowed: %s", allowed.c_str());
  if (row.optional && !row.unset_means.empty()) ImGui::TextDisabled("unset: %s", row.unset_means.c_str());
  ImGui::PopTextWrapPos();
  ImGui::EndTooltip();
}

}  // namespace

WidgetEdit param_widget(const params::ParamInfo& row, const params::Value& value, const params::Value& derived) {
  WidgetEdit edit;
  const bool unset = std::holds_alternative<std::monostate>(value);
  ImGui::PushID(row.key.c_str());
  ImGui::TextUnformatted(row.key.c_str());
  tooltip(row);
  if (row.optional) {
    ImGui::SameLine();
    if (unset) {
      ImGui::TextDisabled("(derived)");
    } else {
      ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f), "(set)");
      ImGui::SameLine();
      edit.reset = ImGui::SmallButton("reset");
    }
  }
  params::Value shown = unset ? derived : value;
  ImGui::SetNextItemWidth(-1.0f);
  if (value_widget(row, shown) && params::check(row, shown).empty()) {
    edit.changed = true;
    edit.value = std::move(shown);
  }
  tooltip(row);
  ImGui::PopID();
  return edit;
}

}  // namespace sansui::viewer

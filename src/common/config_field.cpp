#include "common/config_field.hpp"

#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace crux {

namespace {

std::string bound_text(double value) { return fmt::format("{}", value); }

}  // namespace

bool Bounds::contains(double value) const {
  return (min_open ? value > min : value >= min) && (max_open ? value < max : value <= max);
}

std::string Bounds::summary(bool integer) const {
  const bool has_min = std::isfinite(min), has_max = std::isfinite(max);
  if (has_min && has_max) {
    if (integer && !min_open && !max_open) return fmt::format("{} to {}", bound_text(min), bound_text(max));
    return fmt::format("{}{}, {}{}", min_open ? '(' : '[', bound_text(min), bound_text(max), max_open ? ')' : ']');
  }
  if (has_min) return fmt::format("{} {}", min_open ? ">" : ">=", bound_text(min));
  if (has_max) return fmt::format("{} {}", max_open ? "<" : "<=", bound_text(max));
  return {};
}

std::string Bounds::problem(bool integer) const {
  const bool has_min = std::isfinite(min), has_max = std::isfinite(max);
  std::string text;
  if (has_min && !has_max && min == 0) {
    text = min_open ? "must be positive" : "must be 0 or positive";
  } else if (has_min && has_max && integer && !min_open && !max_open) {
    text = fmt::format("must be from {} to {}", bound_text(min), bound_text(max));
  } else if (has_min && has_max) {
    text = "must be in " + summary(integer);
  } else if (has_min || has_max) {
    text = "must be " + summary(integer);
  }
  return why == nullptr ? text : fmt::format("{} ({})", text, why);
}

template <bool Const>
const char* ConfigFieldOf<Const>::type_name() const {
  static constexpr const char* kNames[] = {"number", "number",  "integer", "integer", "seed",
                                           "seed",   "boolean", "text",    "choice"};
  if (is_path) return "path";
  return kNames[target.index()];
}

template <bool Const>
bool ConfigFieldOf<Const>::is_integer() const {
  return std::holds_alternative<Ref<int>>(target) || std::holds_alternative<Ref<std::optional<int>>>(target);
}

template <bool Const>
std::string ConfigFieldOf<Const>::described_help() const {
  std::vector<std::string> notes;
  if (!unit.empty()) notes.push_back(unit);
  if (const std::string range = bounds.summary(is_integer()); !range.empty()) notes.push_back(range);
  if (const auto* choice = std::get_if<ChoiceTarget<Const>>(&target)) notes.push_back(choice->type->choices());
  return notes.empty() ? help : fmt::format("{} ({})", help, fmt::join(notes, "; "));
}

template struct ConfigFieldOf<false>;
template struct ConfigFieldOf<true>;

}  // namespace crux

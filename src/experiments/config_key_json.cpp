#include "experiments/config_key_json.hpp"

#include <cmath>

namespace crux {

nlohmann::ordered_json config_key_json(const ConstConfigField& field) {
  nlohmann::ordered_json out;
  out["key"] = field.key;
  out["flag"] = flag_for_key(field.key);
  out["type"] = field.type_name();
  nlohmann::ordered_json value = nullptr;
  std::visit(
      [&](auto target) {
        using T = std::remove_cvref_t<std::remove_pointer_t<decltype(target)>>;
        if constexpr (std::is_same_v<T, ChoiceTarget<true>>) {
          const std::string text = target.type->text(target.target);
          if (!text.empty()) value = text;
        } else if constexpr (std::is_same_v<T, std::string>) {
          if (!target->empty()) value = *target;
        } else if constexpr (std::is_same_v<T, std::optional<double>> || std::is_same_v<T, std::optional<int>> ||
                             std::is_same_v<T, std::optional<std::uint64_t>>) {
          if (*target) value = **target;
        } else {
          value = *target;
        }
      },
      field.target);
  out["value"] = std::move(value);
  out["unit"] = field.unit;
  const auto bound = [](double limit) -> nlohmann::ordered_json {
    return std::isfinite(limit) ? nlohmann::ordered_json(limit) : nlohmann::ordered_json(nullptr);
  };
  out["min"] = bound(field.bounds.min);
  out["max"] = bound(field.bounds.max);
  out["min_open"] = field.bounds.min_open;
  out["max_open"] = field.bounds.max_open;
  out["sizes_work"] = field.bounds.sizes_work;
  const auto* choice = std::get_if<ChoiceTarget<true>>(&field.target);
  out["choices"] =
      choice == nullptr ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(choice->type->choices());
  out["help"] = field.described_help();
  return out;
}

}  // namespace crux

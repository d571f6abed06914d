#include "common/json_field.hpp"

#include <fmt/format.h>

#include "common/input_error.hpp"
#include "common/input_file.hpp"
#include "common/printable.hpp"

namespace crux {

std::string json_value_description(const OrderedJson& value) {
  return value.is_number() || value.is_boolean() ? value.dump() : value.type_name();
}

OrderedJson read_json_file(const std::string& file, std::string_view kind) {
  const std::string text = read_input_file(file, kind);
  try {
    return OrderedJson::parse(text);
  } catch (const OrderedJson::exception& e) {
    throw InputError(file, "not JSON: " + printable(e.what()));
  }
}

std::string json_child_path(const std::string& parent, std::string_view key) {
  return parent.empty() ? std::string(key) : fmt::format("{}.{}", parent, key);
}

void JsonField::fail(const std::string& problem) const { throw InputError(file_, problem); }

void JsonField::expect_object() const {
  if (!value_.is_object()) {
    fail(fmt::format("{} must be an object, got {}", path_.empty() ? "the top level" : path_,
                     json_value_description(value_)));
  }
}

JsonField JsonField::operator[](std::string_view key) const {
  expect_object();
  const std::string path = json_child_path(path_, key);
  const auto found = value_.find(key);
  if (found == value_.end()) fail(path + " is missing");
  return {file_, *found, path};
}

JsonField JsonField::operator[](std::size_t index) const {
  if (index >= size()) fail(fmt::format("{} has {} values; there is no [{}]", path_, value_.size(), index));
  return {file_, value_[index], fmt::format("{}[{}]", path_, index)};
}

std::size_t JsonField::size() const {
  if (!value_.is_array()) fail(fmt::format("{} must be an array, got {}", path_, json_value_description(value_)));
  return value_.size();
}

void JsonField::expect_size(std::size_t n) const {
  if (size() != n) fail(fmt::format("{} has {} values, not {}", path_, value_.size(), n));
}

double JsonField::number() const {
  if (!value_.is_number()) fail(fmt::format("{} must be a number, got {}", path_, json_value_description(value_)));
  return value_.get<double>();
}

int JsonField::integer(std::int64_t min, std::int64_t max) const {
  const bool in_range = value_.is_number_unsigned() ? value_.get<std::uint64_t>() <= static_cast<std::uint64_t>(max) &&
                                                          static_cast<std::int64_t>(value_.get<std::uint64_t>()) >= min
                                                    : value_.is_number_integer() && value_.get<std::int64_t>() >= min &&
                                                          value_.get<std::int64_t>() <= max;
  if (!in_range) {
    fail(fmt::format("{} must be an integer from {} to {}, got {}", path_, min, max, json_value_description(value_)));
  }
  return static_cast<int>(value_.get<std::int64_t>());
}

std::uint64_t JsonField::unsigned_integer() const {
  if (!value_.is_number_unsigned() && !(value_.is_number_integer() && value_.get<std::int64_t>() >= 0)) {
    fail(fmt::format("{} must be an integer from 0 to {}, got {}", path_, std::numeric_limits<std::uint64_t>::max(),
                     json_value_description(value_)));
  }
  return value_.get<std::uint64_t>();
}

bool JsonField::boolean() const {
  if (!value_.is_boolean()) {
    fail(fmt::format("{} must be true or false, got {}", path_, json_value_description(value_)));
  }
  return value_.get<bool>();
}

std::string JsonField::string() const {
  if (!value_.is_string()) fail(fmt::format("{} must be a string, got {}", path_, json_value_description(value_)));
  return value_.get<std::string>();
}

}  // namespace crux

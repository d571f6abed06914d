#pragma once
// Checked access to a value of a JSON file crux reads (summary.json, a wall file): the
// value carries its path in the document ("run_facts.transfer[2].wall_pair"), so that
// every error is one line naming the file, the key and what was found there.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <utility>

#include <nlohmann/json.hpp>

namespace crux {

// Ordered, so that a reader may keep the file's order of an object's members.
using OrderedJson = nlohmann::ordered_json;

// What a value is, as a message names it: numbers and booleans by value, the rest by type.
std::string json_value_description(const OrderedJson& value);

// The JSON document in `file`, read as read_input_file reads a `kind` of file:
// InputError(file, "not JSON: ...") when it does not parse.
OrderedJson read_json_file(const std::string& file, std::string_view kind);

// A 3-vector (Eigen's, or any with x(), y() and z()) as the JSON array [x, y, z].
template <typename Vector3>
OrderedJson vector_json(const Vector3& v) {
  return {v.x(), v.y(), v.z()};
}

// `key` under `parent`: "holds[3]" and "radius" give "holds[3].radius", "" and "name" "name".
std::string json_child_path(const std::string& parent, std::string_view key);

class JsonField {
 public:
  // `file` must outlive the field and the fields taken from it.
  JsonField(const std::string& file, const OrderedJson& value, std::string path = "")
      : file_(file), value_(value), path_(std::move(path)) {}

  const OrderedJson& json() const { return value_; }
  const std::string& path() const { return path_; }

  // InputError(file, "<path> must be an object, got <what>") when this is no object.
  void expect_object() const;
  // The member `key`: InputError(file, "<path.key> is missing") when there is none.
  JsonField operator[](std::string_view key) const;
  bool contains(std::string_view key) const { return value_.is_object() && value_.contains(key); }
  // Element `index` of an array: InputError when this is no array or too short.
  JsonField operator[](std::size_t index) const;
  bool is_null() const { return value_.is_null(); }

  // The number of elements of an array: InputError(file, "<path> must be an array, got ...").
  std::size_t size() const;
  // An array of exactly n elements: InputError(file, "<path> has m values, not n").
  void expect_size(std::size_t n) const;

  // InputError(file, "<path> must be <kind>, got <what>") for a value of another type or,
  // for integers, outside [min, max].
  double number() const;
  int integer(std::int64_t min = std::numeric_limits<int>::min(),
              std::int64_t max = std::numeric_limits<int>::max()) const;
  std::uint64_t unsigned_integer() const;  // from 0 to 2^64 - 1: seeds
  bool boolean() const;
  std::string string() const;

  // InputError(file, problem), for a reader's own checks of this value.
  [[noreturn]] void fail(const std::string& problem) const;

 private:
  const std::string& file_;
  const OrderedJson& value_;
  std::string path_;
};

}  // namespace crux

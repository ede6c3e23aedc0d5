// A small strict JSON reader for the files users hand the CLI and the Python door (labels,
// options): values, arrays, objects, strings with the usual escapes (\uXXXX kept as written),
// numbers as doubles. Errors name the file and the character where the text stopped being JSON.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace holefill {

struct JsonValue {
  enum class Type { Null, Bool, Number, String, Array, Object };
  Type type = Type::Null;
  bool boolean = false;
  double number = 0;
  std::string string;
  std::vector<JsonValue> array;
  std::vector<std::pair<std::string, JsonValue>> object;

  const JsonValue* find(const std::string& key) const;  // nullptr when absent or not an object
};

JsonValue parseJson(const std::string& text, const std::string& name = "JSON");

}  // namespace holefill

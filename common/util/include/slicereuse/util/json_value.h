#pragma once
// json_value: a JSON document (the placements file, the printer presets) as a tree with typed
// access that names the place of a wrong value.
// parse_json(text, name) -> the document's value tree, parsed by nlohmann::json (numbers as
// strtod reads them: exactly the double a shortest round-trip or %.17g text came from). Throws
// Error "'name': parse error at line N, column C: what" on a syntax error; nesting deeper than
// 64 is refused.
// Value::at(key, where) / as_*(where) throw Error naming `where` (e.g. "plate 2, member 3")
// when the key is missing or the type differs.
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace slicereuse::detail {

struct JsonValue {
  enum class Type { Null, Bool, Number, String, Array, Object } type = Type::Null;
  bool boolean = false;
  double number = 0;
  std::string text;
  std::vector<JsonValue> items;
  std::map<std::string, JsonValue> fields;

  const JsonValue* find(const std::string& key) const;
  const JsonValue& at(const std::string& key, const std::string& where) const;
  bool as_bool(const std::string& where) const;
  double as_number(const std::string& where) const;
  const std::string& as_string(const std::string& where) const;
  const std::vector<JsonValue>& as_array(const std::string& where) const;
};

JsonValue parse_json(const std::string& text, const std::string& name);

}  // namespace slicereuse::detail

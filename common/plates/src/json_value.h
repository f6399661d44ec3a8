#pragma once
// json_value: a small JSON reader for the placements file (placements_file.cpp); internal.
// parse_json(text, name) -> the document's value tree. Numbers are read as std::from_chars
// reads them (exactly what %.17g wrote); strings take the escapes \" \\ \/ \b \f \n \r \t and
// \uXXXX (written as UTF-8, surrogate pairs joined). Throws Error "'name', line N: what" on the
// first syntax error; nesting deeper than 64 is refused.
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
  double as_number(const std::string& where) const;
  const std::string& as_string(const std::string& where) const;
  const std::vector<JsonValue>& as_array(const std::string& where) const;
};

JsonValue parse_json(const std::string& text, const std::string& name);

}  // namespace slicereuse::detail

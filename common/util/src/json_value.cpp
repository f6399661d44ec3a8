#include "slicereuse/util/json_value.h"

#include <nlohmann/json.hpp>

#include <string>

#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"

namespace slicereuse::detail {
namespace {

constexpr int kMaxDepth = 64;

// nlohmann::json's document as a JsonValue tree, nesting limited (a hostile file could nest
// deeply enough to exhaust the stack of a recursive walk).
JsonValue convert(const nlohmann::json& j, int depth, const std::string& name) {
  if (depth > kMaxDepth) throw Error(format("'%s': nested deeper than %d levels", name.c_str(), kMaxDepth));
  JsonValue v;
  switch (j.type()) {
    case nlohmann::json::value_t::null:
    case nlohmann::json::value_t::discarded:
      break;
    case nlohmann::json::value_t::boolean:
      v.type = JsonValue::Type::Bool;
      v.boolean = j.get<bool>();
      break;
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned:
    case nlohmann::json::value_t::number_float:
      v.type = JsonValue::Type::Number;
      v.number = j.get<double>();
      break;
    case nlohmann::json::value_t::string:
      v.type = JsonValue::Type::String;
      v.text = j.get<std::string>();
      break;
    case nlohmann::json::value_t::array:
      v.type = JsonValue::Type::Array;
      for (const nlohmann::json& item : j) v.items.push_back(convert(item, depth + 1, name));
      break;
    case nlohmann::json::value_t::object:
      v.type = JsonValue::Type::Object;
      for (const auto& [key, item] : j.items()) v.fields.emplace(key, convert(item, depth + 1, name));
      break;
    case nlohmann::json::value_t::binary:
      throw Error("'" + name + "': binary values are not JSON text");
  }
  return v;
}

const char* type_name(JsonValue::Type t) {
  switch (t) {
    case JsonValue::Type::Null: return "null";
    case JsonValue::Type::Bool: return "true or false";
    case JsonValue::Type::Number: return "a number";
    case JsonValue::Type::String: return "a string";
    case JsonValue::Type::Array: return "a list";
    case JsonValue::Type::Object: return "an object";
  }
  return "";
}

void want(const JsonValue& v, JsonValue::Type t, const std::string& where) {
  if (v.type != t) throw Error(where + " is " + type_name(v.type) + ", not " + type_name(t));
}

}  // namespace

const JsonValue* JsonValue::find(const std::string& key) const {
  const auto i = fields.find(key);
  return i == fields.end() ? nullptr : &i->second;
}

const JsonValue& JsonValue::at(const std::string& key, const std::string& where) const {
  want(*this, Type::Object, where);
  const JsonValue* v = find(key);
  if (!v) throw Error(where + " has no \"" + key + "\"");
  return *v;
}

bool JsonValue::as_bool(const std::string& where) const {
  want(*this, Type::Bool, where);
  return boolean;
}

double JsonValue::as_number(const std::string& where) const {
  want(*this, Type::Number, where);
  return number;
}

const std::string& JsonValue::as_string(const std::string& where) const {
  want(*this, Type::String, where);
  return text;
}

const std::vector<JsonValue>& JsonValue::as_array(const std::string& where) const {
  want(*this, Type::Array, where);
  return items;
}

JsonValue parse_json(const std::string& text, const std::string& name) {
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // what() starts with the exception's id ("[json.exception.parse_error.101] "): left out.
    std::string what = e.what();
    const size_t id_end = what.find("] ");
    if (what.rfind("[json.exception", 0) == 0 && id_end != std::string::npos) what = what.substr(id_end + 2);
    throw Error("'" + name + "': " + what);
  }
  return convert(doc, 0, name);
}

}  // namespace slicereuse::detail

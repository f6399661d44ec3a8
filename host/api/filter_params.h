#pragma once
// Typed filter parameters. A filter declares its parameters once, as a ParamList that binds
// every ParamSpec (name, type, label, tooltip, default, allowed values) to a field of the
// filter's own parameter struct P. The list gives the host its ParamSpecs (filter_api.h) and
// reads the host's ParamValues into a P, checking every value once, here: numbers finite and in
// their range, enum indices among their values, required texts not empty. A filter reads only
// P's fields, so reading a parameter its spec does not declare does not compile; a name the spec
// does not declare in the values (a mistyped name from a test or another host) is refused.
//
//   struct SliceParams { double layer_thickness; std::string contour_file; };
//   ParamList<SliceParams> list;
//   list.number(&SliceParams::layer_thickness, "layer_thickness", "Layer thickness (mm)", 0.1,
//               Range::above(0, "mm"), "Distance between planes.")
//       .file(&SliceParams::contour_file, ParamType::FileSave, "contour_file", ...);
//   const SliceParams p = list.read(values);  // Error naming the parameter on a bad value
#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "filter_api.h"
#include "slicereuse/util/error.h"
#include "slicereuse/util/format.h"

namespace slicereuse::plugin {

// The values a number parameter accepts, besides being finite: [min, max], or (min, max] when
// above_min. unit follows the bounds in messages ("mm", "pixels").
struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool above_min = false;
  const char* unit = "";

  static Range any() { return {}; }
  static Range above(double min, const char* unit) { return {min, std::numeric_limits<double>::infinity(), true, unit}; }
  static Range at_least(double min, const char* unit) { return {min, std::numeric_limits<double>::infinity(), false, unit}; }
  static Range between(double min, double max, const char* unit) { return {min, max, false, unit}; }

  // "" when v is allowed, else what it must be, e.g. "greater than 0 mm".
  std::string violated_by(double v) const {
    const std::string u = *unit ? std::string(" ") + unit : "";
    if (!std::isfinite(v)) return "a finite number";
    if (max < std::numeric_limits<double>::infinity() && (v < min || v > max))
      return format("between %g and %g%s", min, max, u.c_str());
    if (above_min && !(v > min)) return format("greater than %g%s", min, u.c_str());
    if (v < min) return format("at least %g%s", min, u.c_str());
    return "";
  }
};

template <class P>
class ParamList {
 public:
  ParamList& number(double P::*field, const char* name, const char* label, double default_value, Range range,
                    const char* tooltip) {
    return add(spec(name, ParamType::Float, label, tooltip, default_value),
               [field, name, range](P& p, const ParamValues& v) { p.*field = checked(v, name, range); });
  }

  ParamList& whole(int P::*field, const char* name, const char* label, int default_value, Range range,
                   const char* tooltip) {
    return add(spec(name, ParamType::Int, label, tooltip, default_value),
               [field, name, range](P& p, const ParamValues& v) { p.*field = int(checked(v, name, range)); });
  }

  ParamList& flag(bool P::*field, const char* name, const char* label, bool default_value, const char* tooltip) {
    return add(spec(name, ParamType::Bool, label, tooltip, default_value ? 1 : 0),
               [field, name](P& p, const ParamValues& v) { p.*field = v.number(name) != 0; });
  }

  // An enum field E whose values 0, 1, ... are named by `names` in the dialog.
  template <class E>
  ParamList& choice(E P::*field, const char* name, const char* label, std::vector<std::string> names,
                    E default_value, const char* tooltip) {
    ParamSpec s = spec(name, ParamType::Enum, label, tooltip, double(default_value));
    s.enum_values = std::move(names);
    return add(s, [field, s](P& p, const ParamValues& v) {
      const double index = v.number(s.name);
      if (!(index >= 0 && index < double(s.enum_values.size())) || index != std::floor(index)) {
        std::string allowed;
        for (size_t i = 0; i < s.enum_values.size(); ++i)
          allowed += (i ? ", " : "") + std::to_string(i) + " (" + s.enum_values[i] + ")";
        throw Error(format("%s must be one of %s, got %g", s.name.c_str(), allowed.c_str(), index));
      }
      p.*field = E(int(index));
    });
  }

  // A file name (type FileOpen or FileSave). when_empty: if given, an empty name is refused
  // with "<name> is empty: <when_empty>"; if null, empty means "no such file".
  ParamList& file(std::string P::*field, ParamType type, const char* name, const char* label,
                  const char* file_filter, const char* when_empty, const char* tooltip) {
    ParamSpec s = spec(name, type, label, tooltip, 0);
    s.file_filter = file_filter;
    if (type == ParamType::FileSave) outputs_.push_back({name, [field](const P& p) { return p.*field; }});
    return add(s, [field, name, when_empty](P& p, const ParamValues& v) {
      p.*field = v.text(name);
      if (when_empty && (p.*field).empty()) throw Error(std::string(name) + " is empty: " + when_empty);
    });
  }

  // A text (type String), as given.
  ParamList& text(std::string P::*field, const char* name, const char* label, const char* default_value,
                  const char* tooltip) {
    ParamSpec s = spec(name, ParamType::String, label, tooltip, 0);
    s.default_text = default_value;
    return add(s, [field, name](P& p, const ParamValues& v) { p.*field = v.text(name); });
  }

  // A list of files to read, as one text (type String): names separated by ';', blanks around
  // each ignored, empty names skipped; empty: none.
  ParamList& file_list(std::vector<std::string> P::*field, const char* name, const char* label, const char* tooltip) {
    return add(spec(name, ParamType::String, label, tooltip, 0), [field, name](P& p, const ParamValues& v) {
      const std::string& text = v.text(name);
      (p.*field).clear();
      for (size_t a = 0; a <= text.size();) {
        size_t b = std::min(text.find(';', a), text.size());
        size_t first = a, last = b;
        while (first < last && std::isspace((unsigned char)text[first])) ++first;
        while (last > first && std::isspace((unsigned char)text[last - 1])) --last;
        if (last > first) (p.*field).push_back(text.substr(first, last - first));
        a = b + 1;
      }
    });
  }

  // For the FileSave parameter added last: the first file the filter writes from it, when that is
  // not the value itself (plate.sl1 gives plate_1.sl1), for outputs().
  ParamList& first_file(std::function<std::string(const P&)> of) {
    outputs_.back().second = std::move(of);
    return *this;
  }

  // A loaded mesh, as the host's reference (Host::mesh_at).
  ParamList& mesh(int P::*field, const char* name, const char* label, const char* tooltip) {
    return add(spec(name, ParamType::Mesh, label, tooltip, 0),
               [field, name](P& p, const ParamValues& v) { p.*field = int(v.number(name)); });
  }

  // Every parameter of `list`, read into the member struct `field` (parameters that several
  // filters share, e.g. the printer's display).
  template <class Q>
  ParamList& include(Q P::*field, const ParamList<Q>& list) {
    for (size_t i = 0; i < list.specs_.size(); ++i) {
      specs_.push_back(list.specs_[i]);
      readers_.push_back([field, read = list.readers_[i]](P& p, const ParamValues& v) { read(p.*field, v); });
    }
    for (const auto& [name, of] : list.outputs_)
      outputs_.push_back({name, [field, of = of](const P& p) { return of(p.*field); }});
    return *this;
  }

  const std::vector<ParamSpec>& specs() const { return specs_; }

  // The files p's FileSave parameters will write (first_file), each named by its parameter.
  std::vector<std::pair<std::string, std::string>> outputs(const P& p) const {
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& [name, of] : outputs_) out.emplace_back(name, of(p));
    return out;
  }

  // The values as a P. Throws Error naming the parameter: one the values lack, one they have
  // that the list does not declare, or a value outside what it accepts.
  P read(const ParamValues& values) const {
    for (const auto& entry : values.numbers) refuse_undeclared(entry.first);
    for (const auto& entry : values.texts) refuse_undeclared(entry.first);
    for (const ParamSpec& s : specs_)
      if (!values.numbers.count(s.name) && !values.texts.count(s.name))
        throw Error("parameter '" + s.name + "' is missing");
    P p{};
    for (const auto& read : readers_) read(p, values);
    return p;
  }

 private:
  template <class>
  friend class ParamList;

  using Reader = std::function<void(P&, const ParamValues&)>;

  static ParamSpec spec(const char* name, ParamType type, const char* label, const char* tooltip, double number) {
    ParamSpec s;
    s.name = name;
    s.type = type;
    s.label = label;
    s.tooltip = tooltip;
    s.default_number = number;
    return s;
  }

  static double checked(const ParamValues& values, const char* name, const Range& range) {
    const double v = values.number(name);
    const std::string must = range.violated_by(v);
    if (!must.empty()) throw Error(format("%s must be %s (got %g)", name, must.c_str(), v));
    return v;
  }

  ParamList& add(ParamSpec s, Reader read) {
    specs_.push_back(std::move(s));
    readers_.push_back(std::move(read));
    return *this;
  }

  void refuse_undeclared(const std::string& name) const {
    std::string names;
    for (const ParamSpec& s : specs_) {
      if (s.name == name) return;
      names += (names.empty() ? "" : ", ") + s.name;
    }
    throw Error("there is no parameter '" + name + "'" +
                (names.empty() ? ": this filter takes none" : " (this filter's parameters are " + names + ")"));
  }

  std::vector<ParamSpec> specs_;
  std::vector<Reader> readers_;
  std::vector<std::pair<std::string, std::function<std::string(const P&)>>> outputs_;
};

}  // namespace slicereuse::plugin

// How values cross the Python boundary, written once for every bind_<area>.cpp: enums as their
// names, numpy arrays and point lists, poses, and the text of __repr__.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <limits>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "vistrack/dubins.hpp"
#include "vistrack/error.hpp"
#include "vistrack/geometry.hpp"
#include "vistrack/limits.hpp"

namespace vistrack::bindings {
// An argument typed int in the signature but taken as given (any object), so that integer()
// range-checks it: pybind's own conversion raises a TypeError naming no field for a negative
// seed, 2**64 or 1e300.
struct AnyInteger {
  pybind11::object value;
};
}  // namespace vistrack::bindings

// Every enum with an EnumNames table (vistrack/error.hpp) crosses the boundary as its name, a
// str; an unknown name is a VistrackError naming the field and the allowed names.
namespace pybind11::detail {
template <class E>
struct type_caster_enum_type_enabled<E, std::enable_if_t<vistrack::has_enum_names<E>::value>> : std::false_type {};

template <class E>
struct type_caster<E, std::enable_if_t<vistrack::has_enum_names<E>::value>> {
  PYBIND11_TYPE_CASTER(E, const_name("str"));
  bool load(handle source, bool) {
    if (!isinstance<str>(source)) return false;
    value = vistrack::from_name<E>(source.cast<std::string>());
    return true;
  }
  static handle cast(E value, return_value_policy, handle) { return str(vistrack::to_string(value)).release(); }
};
template <>
struct type_caster<vistrack::bindings::AnyInteger> {
  PYBIND11_TYPE_CASTER(vistrack::bindings::AnyInteger, const_name("typing.SupportsIndex"));
  bool load(handle source, bool) {
    value.value = reinterpret_borrow<object>(source);
    return true;
  }
  static handle cast(const vistrack::bindings::AnyInteger& given, return_value_policy, handle) {
    return given.value.inc_ref();
  }
};
}  // namespace pybind11::detail

namespace vistrack::bindings {

// `given` as a T in [low, high] (an int or numpy integer; not a bool, a float or text); else
// VistrackError "field = value: must be an integer in [low, high]".
template <class T>
T integer(const AnyInteger& given, const std::string& field, T low = std::numeric_limits<T>::min(),
          T high = std::numeric_limits<T>::max()) {
  namespace py = pybind11;
  const py::handle value = given.value;
  const std::string allowed = "must be an integer in [" + std::to_string(low) + ", " + std::to_string(high) + "]";
  const auto fail = [&] {
    detail::fail_field(field, detail::printable(py::repr(value).cast<std::string>(), false), allowed);
  };
  if (!value || PyBool_Check(value.ptr()) || !PyIndex_Check(value.ptr())) fail();
  const auto number = py::reinterpret_steal<py::int_>(PyNumber_Index(value.ptr()));
  if (!number) throw py::error_already_set();
  if (number < py::int_(low) || number > py::int_(high)) fail();
  return number.cast<T>();
}

// Any array-like of float64, C order (what numpy gives after a cast).
using InputArray = pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>;
// (x, y, psi) as Python passes a pose.
using Pose = std::tuple<double, double, double>;

Configuration configuration(const Pose& pose);

// The names of an enum's values in table order, without the other accepted spellings.
template <class E>
pybind11::tuple enum_names() {
  pybind11::list names;
  for (const EnumName<E>& entry : EnumNames<E>::names)
    if (to_string(entry.value) == entry.name) names.append(entry.name);
  return pybind11::tuple(names);
}

// A 1-D array of the values (bool too).
template <class T>
pybind11::array_t<T> to_numpy(const std::vector<T>& values) {
  pybind11::array_t<T> out(static_cast<pybind11::ssize_t>(values.size()));
  T* data = out.mutable_data();
  for (std::size_t k = 0; k < values.size(); ++k) data[k] = values[k];
  return out;
}

// An (n, 2) array (or a sequence of pairs) as points; Error naming `field` for another shape. The
// values are the callee's to check (each C++ entry point validates its points, naming them).
std::vector<Vec2> to_points(const InputArray& array, const std::string& field);
// A 1-D array as values (not checked: the callee validates what it needs).
std::vector<double> to_values(const InputArray& array, const std::string& field);
// Points as an (n, 2) array.
Points2 to_array(const std::vector<Vec2>& points);

// "Name(key=value, ...)" for __repr__: numbers at their shortest round trip (as in error
// messages), strings quoted.
class Repr {
 public:
  explicit Repr(const std::string& name) : text_(name + "(") {}
  template <class T>
  Repr& add(const char* key, const T& value) {
    return item(std::string(key) + "=" + format(value));
  }
  // A part without key ("valid"); as given.
  Repr& item(const std::string& text) {
    text_ += (first_ ? "" : ", ") + text;
    first_ = false;
    return *this;
  }
  std::string str() const { return text_ + ")"; }

 private:
  template <class T>
  static std::string format(const T& value) {
    if constexpr (std::is_same_v<T, bool>) return value ? "True" : "False";
    else if constexpr (has_enum_names<T>::value) return "'" + to_string(value) + "'";
    else return detail::to_text(value);
  }
  static std::string format(const std::string& value) { return "'" + value + "'"; }
  static std::string format(const Vec2& p) { return "(" + format(p.x()) + ", " + format(p.y()) + ")"; }
  static std::string format(const Vec3& p) {
    return "(" + format(p.x()) + ", " + format(p.y()) + ", " + format(p.z()) + ")";
  }

  std::string text_;
  bool first_ = true;
};

}  // namespace vistrack::bindings

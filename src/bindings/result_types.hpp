// C++ result structs as Python types, each described once by a table of fields.
//
// A field table is a std::tuple of result_field{name, getter}; GECKO_RESULT_FIELD(S, m) names a
// member by itself. From one table come
//   * bind_result<S>(m, "Name", doc, fields): a py::class_ with a read-only property per field,
//     `fields` (the names), a readable __repr__ ("Name(Fn=-2.448406, status=CriticalStatus.converged,
//     ...)") and, for code written when these were dicts, read-only Mapping access (keys, items,
//     values, get, [], in, iter, len; enums there are plain ints, as the dicts had them; deprecated:
//     use the attributes);
//   * columns(rows, n, fields): one numpy array per field over many results (float64 for reals,
//     int8 for bools, int32 for integers and enums), in the table's order;
//   * record(s, fields): one result as a dict {name: value} in the table's order, each value cast
//     as its getter returns it (GECKO_ARRAY_FIELD(S, m) names a std::vector member given as a
//     numpy array; other vectors become lists).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include <pybind11/stl.h>

#include "bindings.hpp"

namespace gecko {
namespace bindings {

template <class Get>
struct result_field {
  const char* name;
  Get get;
};

template <class Get>
result_field<Get> field(const char* name, Get get) {
  return {name, get};
}

#define GECKO_RESULT_FIELD(S, m) ::gecko::bindings::field(#m, [](const S& s) { return s.m; })

// A copy of v as a 1-d numpy array.
template <class V>
py::array_t<V> as_array(const std::vector<V>& v) {
  return py::array_t<V>(static_cast<py::ssize_t>(v.size()), v.data());
}

#define GECKO_ARRAY_FIELD(S, m) ::gecko::bindings::field(#m, [](const S& s) { return ::gecko::bindings::as_array(s.m); })

template <class Fields, class F>
void for_each_field(const Fields& fields, F&& f) {
  std::apply([&](const auto&... x) { (f(x), ...); }, fields);
}

template <class S, class Field>
using field_value_t = std::decay_t<decltype(std::declval<const Field&>().get(std::declval<const S&>()))>;

// The numpy element type of a column of V.
template <class V>
using column_t = std::conditional_t<std::is_same<V, bool>::value, std::int8_t,
                                    std::conditional_t<std::is_floating_point<V>::value, V, std::int32_t>>;

// A value as the former dicts held it: enums as plain ints, everything else cast as is.
template <class V>
py::object plain_value(const V& v) {
  if constexpr (std::is_enum<V>::value) return py::int_(static_cast<int>(v));
  else return py::cast(v);
}

// Columns of n results: {name: numpy array of length n}.
template <class S, class Fields>
py::dict columns(const S* rows, std::size_t n, const Fields& fields) {
  py::dict d;
  for_each_field(fields, [&](const auto& f) {
    using C = column_t<field_value_t<S, std::decay_t<decltype(f)>>>;
    py::array_t<C> a(static_cast<py::ssize_t>(n));
    C* p = a.mutable_data();
    for (std::size_t i = 0; i < n; ++i) p[i] = static_cast<C>(f.get(rows[i]));
    d[f.name] = a;
  });
  return d;
}

// One result as a dict: {name: the getter's value, cast to Python}.
template <class S, class Fields>
py::dict record(const S& s, const Fields& fields) {
  py::dict d;
  for_each_field(fields, [&](const auto& f) { d[f.name] = f.get(s); });
  return d;
}

template <class S, class Fields>
py::class_<S> bind_result(py::module_& m, const char* name, const char* doc, const Fields& fields) {
  py::class_<S> cls(m, name, doc);
  std::vector<std::string> names;
  for_each_field(fields, [&](const auto& f) {
    const auto get = f.get;
    cls.def_property_readonly(f.name, [get](const S& s) { return get(s); });
    names.emplace_back(f.name);
  });
  cls.attr("fields") = py::tuple(py::cast(names));
  const std::string type_name = name;
  cls.def("__repr__", [fields, type_name](const S& s) {
    std::string out = type_name + "(";
    const char* sep = "";
    for_each_field(fields, [&](const auto& f) {
      const auto v = f.get(s);
      const py::object o = py::cast(v);
      std::string text;
      if constexpr (std::is_enum<std::decay_t<decltype(v)>>::value)
        text = py::str(o.attr("__class__").attr("__name__")).cast<std::string>() + "." +
               py::str(o.attr("name")).cast<std::string>();
      else
        text = py::repr(o).cast<std::string>();
      out += sep;
      out += f.name;
      out += "=" + text;
      sep = ", ";
    });
    return out + ")";
  });
  // Deprecated Mapping access (these results were dicts before 0.2).
  auto item = [fields](const S& s, const std::string& key) {
    py::object out;
    bool found = false;
    for_each_field(fields, [&](const auto& f) {
      if (!found && key == f.name) {
        out = plain_value(f.get(s));
        found = true;
      }
    });
    if (!found) throw py::key_error(key);
    return out;
  };
  cls.def("__getitem__", item, py::arg("key"),
          "Deprecated dict-style access (enums as ints); use the attribute of that name.");
  cls.def("keys", [names](const S&) { return names; }, "Deprecated: the field names (see `fields`).");
  cls.def("__iter__", [names](const S&) { return py::iter(py::cast(names)); });
  cls.def("__len__", [names](const S&) { return names.size(); });
  cls.def("__contains__", [names](const S&, const py::object& key) {
    if (!py::isinstance<py::str>(key)) return false;
    const auto k = key.cast<std::string>();
    for (const auto& n : names)
      if (n == k) return true;
    return false;
  });
  cls.def("get", [item](const S& s, const std::string& key, const py::object& fallback) {
    try {
      return item(s, key);
    } catch (const py::key_error&) {
      return fallback;
    }
  }, py::arg("key"), py::arg("default") = py::none(), "Deprecated dict-style access.");
  cls.def("items", [item, names](const S& s) {
    py::list out;
    for (const auto& n : names) out.append(py::make_tuple(n, item(s, n)));
    return out;
  }, "Deprecated dict-style access.");
  cls.def("values", [item, names](const S& s) {
    py::list out;
    for (const auto& n : names) out.append(item(s, n));
    return out;
  }, "Deprecated dict-style access.");
  return cls;
}

}  // namespace bindings
}  // namespace gecko

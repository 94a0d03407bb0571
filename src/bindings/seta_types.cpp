// The seta domain as Python types: the two-level seta design (fields, defaults, admissible ranges,
// the one validation, all from gecko/seta/two_level_seta.hpp) and the status enums as IntEnums.
// python/gecko/seta.py derives DESIGN_FIELDS and the status tables from these; nothing in Python
// lists the fields or the status codes again.
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <limits>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include <pybind11/native_enum.h>

#include "bindings.hpp"
#include "gecko/friction/fit.hpp"
#include "gecko/seta.hpp"

namespace gecko {
namespace bindings {
namespace {

using policies::default_policy;
using Design = TwoLevelSeta<double>;

// A float as Python writes it (repr), so that the design's repr can be pasted back.
std::string float_repr(double v) { return py::repr(py::float_(v)).cast<std::string>(); }

std::vector<std::string> names_of_fields() {
  std::vector<std::string> out;
  for (const auto& f : seta_design_fields<double>()) out.emplace_back(f.name);
  return out;
}

std::string design_repr(const Design& s) {
  std::string out = "SetaDesign(";
  const char* sep = "";
  for (const auto& f : seta_design_fields<double>()) {
    out += sep;
    out += f.name;
    out += "=" + float_repr(s.*(f.member));
    sep = ", ";
  }
  return out + ")";
}

void bind_design(py::module_& m) {
  const auto& fields = seta_design_fields<double>();
  const Design defaults{};
  py::class_<Design> cls(m, "SetaDesign",
                         "A two-level seta design (the fields in `fields`), validated on construction; "
                         "defaults: the paper's reference scene.");
  // Keyword arguments named by the field table (any subset; the others keep the defaults).
  cls.def(py::init([](const py::kwargs& kwargs) {
            Design s;
            for (const auto& item : kwargs) {
              const auto key = item.first.cast<std::string>();
              const seta_design_field<double>* field = nullptr;
              for (const auto& f : seta_design_fields<double>())
                if (key == f.name) field = &f;
              if (field == nullptr)
                throw py::type_error("gecko.SetaDesign: unknown field '" + key + "'; the fields are " +
                                     py::str(", ").attr("join")(py::cast(names_of_fields())).cast<std::string>());
              try {
                s.*(field->member) = item.second.cast<double>();
              } catch (const py::cast_error&) {
                throw py::type_error("gecko.SetaDesign: " + key + " must be a number, got " +
                                     py::repr(item.second).cast<std::string>());
              }
            }
            detail::check_seta<double, default_policy>(s, "gecko.SetaDesign");
            return s;
          }),
          "SetaDesign(**fields): any of the fields by name (keywords only), the others their defaults.");
  // Read-only fields: a design is validated once, at construction.
  for (const auto& f : fields) {
    const auto member = f.member;
    cls.def_property_readonly(f.name, [member](const Design& s) { return s.*member; });
  }
  py::tuple names(fields.size());
  py::dict defaults_d, domain, descriptions;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const auto& f = fields[i];
    names[i] = py::str(f.name);
    defaults_d[f.name] = defaults.*(f.member);
    domain[f.name] = py::make_tuple(f.lower, f.upper, f.lower_inclusive, f.infinity_allowed, f.range);
    descriptions[f.name] = f.description;
  }
  cls.attr("fields") = names;
  cls.attr("defaults") = defaults_d;
  // name -> (lower, upper, lower inclusive, infinity allowed, the range as the error states it)
  cls.attr("domain") = domain;
  cls.attr("descriptions") = descriptions;
  cls.def_static("admissible", [](const std::string& name, double value) {
    for (const auto& f : seta_design_fields<double>())
      if (name == f.name) return f.admissible(value);
    throw py::key_error("gecko.SetaDesign.admissible: unknown field '" + name + "'");
  }, py::arg("name"), py::arg("value"),
     "Whether one field's value lies in its admissible range (the joint condition alpha1 + alpha2 < pi/2 "
     "is checked on construction).");
  cls.def_property_readonly("ft_max", [](const Design& s) { return ft_max(s); },
                            "(Ft)max = sqrt(2 EA2 w), the end of the critical line.");
  cls.def("check_ft", [](const Design& s, double Ft) {
    detail::check_ft<double, default_policy>(Ft, ft_max(s), "gecko.SetaDesign");
  }, py::arg("Ft"), "Raises ValueError unless Ft is finite and at most (Ft)max.");
  cls.def("to_array", [](const Design& s) {
    py::array_t<double> out(static_cast<py::ssize_t>(seta_design_fields<double>().size()));
    std::size_t i = 0;
    for (const auto& f : seta_design_fields<double>()) out.mutable_data()[i++] = s.*(f.member);
    return out;
  }, "The nine fields as a float64 array in the order of `fields`.");
  cls.def("__repr__", &design_repr);
  cls.def("__eq__", [](const Design& a, const Design& b) {
    for (const auto& f : seta_design_fields<double>())
      if (!(a.*(f.member) == b.*(f.member))) return false;
    return true;
  });
  cls.attr("__hash__") = py::none();
}

// One IntEnum from its members (name, value, optional doc): the one recipe of every status enum.
template <class E>
struct enum_member {
  const char* name;
  E value;
  const char* doc = nullptr;
};

template <class E>
void bind_int_enum(py::module_& m, const char* name, const char* doc, std::initializer_list<enum_member<E>> members) {
  py::native_enum<E> e(m, name, "enum.IntEnum", doc);
  for (const auto& v : members) e.value(v.name, v.value, v.doc);
  e.finalize();
}

void bind_enums(py::module_& m) {
  using cs = critical_status;
  bind_int_enum<cs>(m, "CriticalStatus", "Status of a critical state (gecko/seta/solve_critical.hpp).", {
      {"converged", cs::converged},
      {"not_converged", cs::not_converged, "Newton did not converge from its guess"},
      {"no_critical_state", cs::no_critical_state, "the line followed from Ft = 0 does not reach this Ft"},
      {"unsupported_state", cs::unsupported_state,
       "the state leaves the model: past the edge of its forms, or past the line's first state compressed to zero length"},
      {"singular", cs::singular, "singular Jacobian: Ft at a fold of the line"},
      {"invalid_input", cs::invalid_input, "bad input under errors='nan'"},
      {"not_reached", cs::not_reached, "the followed line was given up before this Ft: unknown, not 'none'"},
      {"inadmissible", cs::inadmissible, "solves the equations, but the seta crosses the substrate, is compressed to zero length, or exceeds the strain limit"},
  });
  using le = line_end;
  bind_int_enum<le>(m, "LineEnd", "Why a followed critical line stopped.", {
      {"reached_ft_end", le::reached_ft_end}, {"reached_ft_max", le::reached_ft_max},
      {"turned_back", le::turned_back}, {"no_convergence", le::no_convergence},
      {"unsupported_state", le::unsupported_state}, {"max_points", le::max_points},
      {"no_natural_state", le::no_natural_state}, {"stalled", le::stalled},
  });
  using ms = minimum_status;
  bind_int_enum<ms>(m, "MinimumStatus", "Where the most tensile critical Fn lies and how far it is established.", {
      {"stationary", ms::stationary}, {"range_start", ms::range_start}, {"range_end", ms::range_end},
      {"line_incomplete", ms::line_incomplete}, {"not_certified", ms::not_certified},
      {"admissible_end", ms::admissible_end}, {"no_admissible_state", ms::no_admissible_state},
  });
  using fs = fit_status;
  bind_int_enum<fs>(m, "FitStatus", "Outcome of a Levenberg-Marquardt fit.", {
      {"converged", fs::converged}, {"max_iterations", fs::max_iterations}, {"singular", fs::singular},
      {"not_identifiable", fs::not_identifiable}, {"no_progress", fs::no_progress},
      {"non_finite", fs::non_finite},
  });
}

}  // namespace

void bind_seta_types(py::module_& m) {
  bind_design(m);
  bind_enums(m);
}

}  // namespace bindings
}  // namespace gecko

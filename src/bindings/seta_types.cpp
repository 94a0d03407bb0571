// The seta domain as Python types: the two-level seta design (fields, defaults, admissible ranges,
// the one validation, all from gecko/seta/two_level_seta.hpp) and the status enums as IntEnums.
// python/gecko/seta.py derives DESIGN_FIELDS and the status tables from these; nothing in Python
// lists the fields or the status codes again.
#include <cmath>
#include <cstddef>
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

void bind_enums(py::module_& m) {
  py::native_enum<critical_status>(m, "CriticalStatus", "enum.IntEnum",
                                   "Status of a critical state (gecko/seta/solve_critical.hpp).")
      .value("converged", critical_status::converged)
      .value("not_converged", critical_status::not_converged, "Newton did not converge from its guess")
      .value("no_critical_state", critical_status::no_critical_state,
             "the line followed from Ft = 0 does not reach this Ft")
      .value("unsupported_state", critical_status::unsupported_state, "the state leaves the model's forms")
      .value("singular", critical_status::singular, "singular Jacobian: Ft at a fold of the line")
      .value("invalid_input", critical_status::invalid_input, "bad input under errors='nan'")
      .value("not_reached", critical_status::not_reached,
             "the followed line was given up before this Ft: unknown, not 'none'")
      .value("inadmissible", critical_status::inadmissible,
             "solves the equations, but the seta crosses the substrate or the strain limit")
      .finalize();
  py::native_enum<line_end>(m, "LineEnd", "enum.IntEnum", "Why a followed critical line stopped.")
      .value("reached_ft_end", line_end::reached_ft_end)
      .value("reached_ft_max", line_end::reached_ft_max)
      .value("turned_back", line_end::turned_back)
      .value("no_convergence", line_end::no_convergence)
      .value("unsupported_state", line_end::unsupported_state)
      .value("max_points", line_end::max_points)
      .value("no_natural_state", line_end::no_natural_state)
      .value("stalled", line_end::stalled)
      .finalize();
  py::native_enum<minimum_status>(m, "MinimumStatus", "enum.IntEnum",
                                  "Where the most tensile critical Fn lies and how far it is established.")
      .value("stationary", minimum_status::stationary)
      .value("range_start", minimum_status::range_start)
      .value("range_end", minimum_status::range_end)
      .value("line_incomplete", minimum_status::line_incomplete)
      .value("not_certified", minimum_status::not_certified)
      .value("admissible_end", minimum_status::admissible_end)
      .value("no_admissible_state", minimum_status::no_admissible_state)
      .finalize();
  py::native_enum<fit_status>(m, "FitStatus", "enum.IntEnum", "Outcome of a Levenberg-Marquardt fit.")
      .value("converged", fit_status::converged)
      .value("max_iterations", fit_status::max_iterations)
      .value("singular", fit_status::singular)
      .value("not_identifiable", fit_status::not_identifiable)
      .value("no_progress", fit_status::no_progress)
      .value("non_finite", fit_status::non_finite)
      .finalize();
}

}  // namespace

void bind_seta_types(py::module_& m) {
  bind_design(m);
  bind_enums(m);
}

}  // namespace bindings
}  // namespace gecko

"""The seta domain bound from C++ (src/bindings/seta_types.cpp): the design type with its fields,
defaults, admissible ranges and one validation, the status IntEnums, and the Python layers that
read them instead of keeping copies."""
import enum
import inspect
import math

import numpy as np
import pytest

import gecko
from gecko import _core, designs, seta
from gecko.seta import DESIGN_FIELDS, CriticalStatus, LineEnd, MinimumStatus, SetaDesign

# The field order every flat design array uses (kernels, sensitivities' columns, sweep tables).
ORDER = ("EI1", "EI2", "EA1", "EA2", "l1", "l2", "alpha1", "alpha2", "w")


def test_design_fields_come_from_the_bound_type_in_kernel_order():
    assert DESIGN_FIELDS == tuple(SetaDesign.fields) == ORDER
    assert gecko.TwoLevelSeta._FIELDS is DESIGN_FIELDS
    assert designs.FIELDS is DESIGN_FIELDS
    assert tuple(inspect.signature(gecko.TwoLevelSeta).parameters) == DESIGN_FIELDS
    # the flat array order is the order the kernels read: sensitivities name their columns so
    assert gecko.TwoLevelSeta().sensitivities([1.0])["parameters"] == list(DESIGN_FIELDS)


def test_defaults_are_the_reference_scene():
    py = gecko.TwoLevelSeta()
    d = SetaDesign()
    for f in DESIGN_FIELDS:
        assert SetaDesign.defaults[f] == getattr(d, f)
        if f.startswith("alpha"):
            # Python's angles are math.pi / 6, C++'s the correctly rounded pi/6: one ulp apart
            assert getattr(py, f) == getattr(d, f) - math.ulp(getattr(d, f)), f
        else:
            assert getattr(py, f) == getattr(d, f), f
    assert [getattr(d, f) for f in ("EI1", "EI2", "EA2", "l1", "l2", "w")] == [5.0, 2.0, 50.0, 1.0, 0.1, 1.0]
    assert d.EA1 == math.inf


def test_repr_is_readable_and_round_trips():
    d = SetaDesign(EI1=3.5, alpha2=0.0)
    text = repr(d)
    assert text.startswith("SetaDesign(EI1=3.5, EI2=2.0, EA1=inf, EA2=50.0, ")
    assert eval(text, {"SetaDesign": SetaDesign, "inf": math.inf}) == d
    np.testing.assert_array_equal(d.to_array(), [getattr(d, f) for f in DESIGN_FIELDS])
    assert d.ft_max == math.sqrt(2 * 50.0 * 1.0)


# Per field: values just outside its admissible range, and its edges that are inside.
OUTSIDE = {f: [0.0, -1.0, math.nan, math.inf] for f in ("EI1", "EI2", "l1", "l2", "w")}
OUTSIDE.update({"EA1": [0.0, -1.0, math.nan, -math.inf], "EA2": [0.0, -1.0, math.nan, -math.inf],
                "alpha1": [0.0, -0.1, math.pi / 2, math.nan], "alpha2": [-1e-300, math.nan, math.pi / 2]})
INSIDE = {"EA1": [math.inf, 1e-300], "EA2": [math.inf], "alpha2": [0.0], "alpha1": [1e-300], "EI1": [1e300]}


@pytest.mark.parametrize("field", ORDER)
def test_one_validation_names_the_field_and_its_range(field):
    lo, hi, lo_incl, inf_ok, text = SetaDesign.domain[field]
    for v in OUTSIDE[field]:
        assert not SetaDesign.admissible(field, v)
        kw = {field: v}
        if field == "alpha1" and v == math.pi / 2:
            kw["alpha2"] = 0.0
        with pytest.raises(ValueError, match=f"{field} = .* is out of range: need {re_escape(text)}"):
            SetaDesign(**kw)
        # the Python class validates through the same C++ check, with the same message
        with pytest.raises(ValueError, match=re_escape(text)):
            gecko.TwoLevelSeta(**kw)
    for v in INSIDE.get(field, []):
        assert SetaDesign.admissible(field, v)
        kw = {field: v}
        if field == "alpha1":
            kw["alpha2"] = 0.0
        SetaDesign(**kw)
        gecko.TwoLevelSeta(**kw)
    assert inf_ok == (field in ("EA1", "EA2"))
    assert lo_incl == (field == "alpha2")


def re_escape(s):
    import re
    return re.escape(s)


def test_the_joint_angle_condition_is_checked_after_the_fields():
    with pytest.raises(ValueError, match=r"alpha1 \+ alpha2 = .* pi/2"):
        SetaDesign(alpha1=1.0, alpha2=0.6)
    with pytest.raises(KeyError):
        SetaDesign.admissible("EI3", 1.0)


def test_construction_takes_the_fields_by_name_only():
    with pytest.raises(TypeError, match="unknown field 'EI3'; the fields are EI1, EI2, EA1"):
        SetaDesign(EI3=1.0)
    with pytest.raises(TypeError):
        SetaDesign(5.0)
    with pytest.raises(TypeError, match="EI1 must be a number"):
        SetaDesign(EI1="stiff")
    assert SetaDesign(EI1=7) == SetaDesign(EI1=7.0)


def test_designs_are_read_only_values():
    d = SetaDesign()
    with pytest.raises(AttributeError):
        d.EI1 = -1.0
    assert d == SetaDesign() and d != SetaDesign(EI1=4.0)


def test_status_enums_are_int_enums_with_the_display_tables_keyed_by_them():
    for e in (CriticalStatus, LineEnd, MinimumStatus, gecko.FitStatus):
        assert issubclass(e, enum.IntEnum)
    assert [int(s) for s in CriticalStatus] == list(range(8))
    assert CriticalStatus.inadmissible == 7 and CriticalStatus(7).name == "inadmissible"
    assert set(seta.STATUS) == set(CriticalStatus)
    assert set(seta._LINE_END) == set(LineEnd)
    assert {MinimumStatus(k).name: v for k, v in seta._MIN_STATUS.items()} == {
        m.name: m.name for m in MinimumStatus}
    assert [m.name for m in gecko.FitStatus] == ["converged", "max_iterations", "singular",
                                                 "not_identifiable", "no_progress", "non_finite"]
    for name in ("CriticalStatus", "LineEnd", "MinimumStatus", "SetaDesign", "DESIGN_FIELDS"):
        assert name in gecko.__all__ and hasattr(gecko, name)
    assert _core.CriticalStatus is CriticalStatus


def test_contact_status_is_the_bound_cpp_enum_with_its_public_names():
    from gecko.seta import ContactStatus
    assert ContactStatus is _core.ContactStatus and issubclass(ContactStatus, enum.IntEnum)
    assert gecko.ContactStatus is ContactStatus and "ContactStatus" in gecko.__all__
    assert [(m.name, int(m)) for m in ContactStatus] == [
        ("CONVERGED", 0), ("NOT_CONVERGED", 1), ("NO_CONTACT", 2), ("UNSUPPORTED_STATE", 3),
        ("BEYOND_JOINT", 4), ("INVALID_INPUT", 5), ("SEVERAL_EQUILIBRIA", 6), ("INADMISSIBLE", 7)]
    # The integers of the result arrays are the C++ values: each converts to its member.
    st = gecko.TwoLevelSeta().contact_state([-1.0, -5.0, 3.0], 2.0)
    assert [ContactStatus(int(k)) for k in st.status] == [
        ContactStatus.CONVERGED, ContactStatus.NO_CONTACT, ContactStatus.BEYOND_JOINT]
    assert list(st.status_names()) == ["CONVERGED", "NO_CONTACT", "BEYOND_JOINT"]


def test_results_carry_enum_members_beside_their_texts():
    s = gecko.TwoLevelSeta()
    line = s.critical_line()
    assert isinstance(line.end_code, LineEnd)
    assert seta._LINE_END[line.end_code] == line.end
    c = s.characteristics()
    assert c.end_code == LineEnd.reached_ft_max and c.end == seta._LINE_END[LineEnd.reached_ft_max]
    assert isinstance(c.min_status_code, MinimumStatus) and c.min_status == c.min_status_code.name
    at = s.critical_line(Ft=[0.0, 1.0])
    assert np.all(at.status == CriticalStatus.converged)


def test_fit_status_code_matches_its_text():
    V = np.geomspace(1e-6, 1e-3, 12)
    ss = gecko.steady_sliding(V, gecko.FIG6_VISCOELASTIC)
    fit = gecko.fit_steady_sliding(V, ss.F_par, ss.F_perp)
    assert fit.status_code == gecko.FitStatus[fit.status]


def test_bounds_ranges_follow_the_bound_domain():
    # the texts the sweep's bounds errors have always used, now derived from the C++ ranges
    assert designs._DOMAIN == {
        "EI1": (0.0, math.inf, False, "0 < EI1 < inf"), "EI2": (0.0, math.inf, False, "0 < EI2 < inf"),
        "EA1": (0.0, math.inf, False, "0 < EA1 < inf (inf: inextensible, fix it instead of sampling)"),
        "EA2": (0.0, math.inf, False, "0 < EA2 < inf (inf: inextensible, fix it instead of sampling)"),
        "l1": (0.0, math.inf, False, "0 < l1 < inf"), "l2": (0.0, math.inf, False, "0 < l2 < inf"),
        "alpha1": (0.0, math.pi / 2, False, "0 < alpha1 < pi/2"),
        "alpha2": (0.0, math.pi / 2, True, "0 <= alpha2 < pi/2"),
        "w": (0.0, math.inf, False, "0 < w < inf"),
    }
    from gecko.optimize.space import _DOMAIN
    assert {k: v[2] for k, v in _DOMAIN.items()} == {
        **{k: "(0, inf)" for k in ("EI1", "EI2", "EA1", "EA2", "l1", "l2", "w", "EI2/EI1", "l2/l1")},
        "alpha1": "(0, pi/2)", "alpha2": "[0, pi/2)", "alpha1+alpha2": "(0, pi/2)"}


def test_scene_parameters_are_built_from_the_design_type():
    from gecko.scene.models import SETA_PARAMS
    assert tuple(p.name for p in SETA_PARAMS) == DESIGN_FIELDS
    by = {p.name: p for p in SETA_PARAMS}
    assert by["EI1"].symbol == "EI₁" and by["alpha2"].symbol == "α₂"
    assert by["alpha1"].default == math.pi / 6 and by["EA1"].default == math.inf
    assert by["EI1"].doc == "bending stiffness of the beam (level 1)"
    assert by["EA2"].check(math.inf) is None and by["EI1"].check(math.inf) == "need 0 < value < inf"
    assert by["alpha2"].check(0.0) is None and by["alpha1"].check(0.0) is not None

"""tools/elliptic_accuracy.py, the README's elliptic accuracy table from the C++ tests' tallies: the
parse of Catch2's XML report (the worst error and the bound of the test case that reports it), the
refusal of a report that lacks a row, and the README rewrite between the markers. On a made-up
report; no C++ build, about a second."""
import importlib.util
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
_spec = importlib.util.spec_from_file_location("elliptic_accuracy", ROOT / "tools" / "elliptic_accuracy.py")
acc = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(acc)


def _case(name, warning):
    return (f'<TestCase name="{name}"><Section name="s"><Warning>\n  {warning}\n    bulk: 1 eps (3 rows)\n'
            f'</Warning></Section><OverallResult success="true"/></TestCase>')


def _report(skip=None):
    cases = []
    for label, name, suffix in acc.ROWS:
        if (name, suffix) == skip:
            continue
        for t in ("double", "long double"):
            if name == "carlson_rj":
                cases.append(_case(f"carlson_rj: mpmath table: &lt;= 4 eps (p.v.: 4 eps x cancellation) - {t}",
                                   f"carlson_rj&lt;{t}>: p > 0 worst 3.02723 eps; p &lt; 0 worst err / (4 cancel) = 0.6"))
            elif suffix:
                cases.append(_case(f"ellint_f, ellint_e at the edge: F &lt;= 3 eps, E &lt;= 4 eps ({t})",
                                   f"{name}&lt;{t}>{suffix}: max error 2.5 eps over 40 rows (table row 7)"))
            else:
                cases.append(_case(f"{name}: mpmath table: &lt;= 3 eps - {t}",
                                   f"{name}&lt;{t}>: max error 1.25 eps over 100 rows (table row 3)"))
    return "<Catch><Group name='test_elliptic'>" + "".join(cases) + "</Group></Catch>"


def test_parse_reads_the_worst_error_and_the_asserted_bound():
    found = acc.parse_warnings(_report())
    assert found[("carlson_rf", "", "double")] == (1.25, 3.0)
    assert found[("carlson_rj", "", "long double")] == (3.02723, 4.0)
    # one test case asserting F <= 3 and E <= 4: each tally gets its own function's bound
    assert found[("ellint_f", ", m > 1 at the edge", "double")] == (2.5, 3.0)
    assert found[("ellint_e", ", m > 1 at the edge", "double")] == (2.5, 4.0)


def test_table_has_every_row_and_no_float_where_none_was_measured():
    body = acc.table(acc.parse_warnings(_report()))
    rows = [l for l in body.splitlines() if l.startswith("| ") and not l.startswith("| function")]
    assert len(rows) == len(acc.ROWS)
    assert rows[0] == "| R_F | 1.25 | 1.25 | — | 3 |"
    assert "| E, m > 1 next to sin²φ = 1/m | 2.5 | 2.5 | — | 4 |" in rows


def test_a_missing_tally_is_refused_not_left_blank():
    with pytest.raises(SystemExit, match="carlson_rd<double>"):
        acc.table(acc.parse_warnings(_report(skip=("carlson_rd", ""))))


def test_readme_rewrite_touches_only_the_text_between_the_markers():
    text = f"before\n{acc.BEGIN}\nold table\n{acc.END}\nafter\n"
    new = acc.replace_between(text, "| new |")
    assert new == f"before\n{acc.BEGIN}\n\n| new |\n\n{acc.END}\nafter\n"
    with pytest.raises(SystemExit):
        acc.replace_between("no markers", "| new |")


def test_the_committed_readme_has_the_markers_once():
    readme = (ROOT / "README.md").read_text()
    assert readme.count(acc.BEGIN) == 1 and readme.count(acc.END) == 1

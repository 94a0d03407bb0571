"""The pure-Python parts of the run-time-against-error harness (bench/tradeoff): Pareto fronts, the
results-file round trip, the GECKOBENCH1 reader, the error measure, and the README generator on a
temporary README and a tiny results folder. No C++ build, no timing (speed is never asserted);
runs in about a second."""
import importlib.util
import json
import math
import pathlib

import numpy as np
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
TRADEOFF = ROOT / "bench" / "tradeoff"


def _load(name):
    spec = importlib.util.spec_from_file_location(f"tradeoff_{name}", TRADEOFF / f"{name}.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


run = _load("run")
readme_section = _load("readme_section")


def test_pareto_front_known_set():
    # (time, error): 0, 2, 4 are the front; 1 is dominated by 0 (slower, worse); 3 is dominated by 2
    # (same time, worse error); 5 ties 4 exactly in error but is slower; 6 is not finite.
    pts = [(1.0, 100.0), (2.0, 200.0), (3.0, 10.0), (3.0, 11.0), (10.0, 1.0), (20.0, 1.0), (0.5, math.nan)]
    assert run.pareto_front(pts) == [0, 2, 4]


def test_pareto_front_edge_cases():
    assert run.pareto_front([]) == []
    assert run.pareto_front([(1.0, 1.0)]) == [0]
    # a point both fastest and most accurate dominates everything
    assert run.pareto_front([(5.0, 5.0), (1.0, 0.5), (2.0, 3.0)]) == [1]
    # inf errors (a method that failed everywhere) never join the front
    assert run.pareto_front([(1.0, math.inf), (2.0, 1.0)]) == [1]


def test_rel_err_eps_counts_in_eps_and_skips_nonfinite():
    hi = np.array([1.0, 2.0, 4.0, 8.0])
    lo = np.array([0.0, 0.0, 0.0, 0.0])
    eps = 2.0 ** -52
    got = np.array([1.0 + eps, 2.0, 4.0 - 3 * 4 * eps / 2, np.nan])
    mx, rms, bad = run.rel_err_eps(got, hi, lo)
    assert bad == 1
    assert mx == pytest.approx(1.5, rel=1e-12)
    # the sub-ulp tail lo is part of the reference: got == hi is then |lo / ref| away
    mx2, _, _ = run.rel_err_eps(np.array([1.0]), np.array([1.0]), np.array([eps / 4]))
    assert mx2 == pytest.approx(0.25, rel=1e-9)


def test_read_column_file_roundtrip(tmp_path):
    x = np.array([1.5, -2.0, 3.25])
    lo = np.array([0.5, 0.25, -0.125], dtype=np.float32)
    path = tmp_path / "t.bin"
    with open(path, "wb") as f:
        f.write(b"GECKOBENCH1 n=3 columns=x:f8,x_lo:f4\n")
        f.write(x.astype("<f8").tobytes())
        f.write(lo.astype("<f4").tobytes())
    cols = run.read_column_file(path)
    assert list(cols) == ["x", "x_lo"]
    np.testing.assert_array_equal(cols["x"], x)
    np.testing.assert_array_equal(cols["x_lo"], lo.astype(np.float64))
    path.write_bytes(path.read_bytes() + b"\0")
    with pytest.raises(ValueError, match="size"):
        run.read_column_file(path)


def test_committed_rd_rj_data_are_readable():
    for name, key in (("carlson_rd", "RD"), ("carlson_rj", "RJ")):
        cols = run.read_column_file(TRADEOFF / "data" / f"{name}.bin")
        assert len(cols[key]) == len(cols["x"]) >= 1000
        assert np.all(np.isfinite(cols[key])) and np.all(cols[key] > 0)


def test_parse_seta_csv_names_with_commas():
    text = ("method,setting,us_per_point,max_rel_err_Fn,failed_points\n"
            "gecko::critical_line_at,tolerance 1e-03,1.2,3e-14,0\n"
            "GSL hybridsj, same residual,test_delta 1e-06,2.9,9.9e-10,0\n"
            "batch 200 designs x 20 Ft,1 thread,15.5,,\n")
    rows = run.parse_seta_csv(text)
    assert rows[0] == ("gecko::critical_line_at", "tolerance 1e-03", "1.2", "3e-14", "0")
    assert rows[1] == ("GSL hybridsj, same residual", "test_delta 1e-06", "2.9", "9.9e-10", "0")
    assert rows[2][:2] == ("batch 200 designs x 20 Ft", "1 thread")


def _tiny_results(tmp_path):
    rows = [
        run.make_row(family="F", method="gecko::ellint_f", setting="full", input_set="S", n=10,
                     time_per_call_ns=40.0, max_err=2.0, rms_err=0.5, unit="eps", failed=0, source="t"),
        run.make_row(family="F", method="gecko::ellint_f", setting="precision<32>", input_set="S", n=10,
                     time_per_call_ns=30.0, max_err=3e4, rms_err=3e3, unit="eps", failed=0, source="t"),
        run.make_row(family="F", method="boost::math::ellint_1", setting="promote_double<false>", input_set="S",
                     n=10, time_per_call_ns=80.0, max_err=19.0, rms_err=0.7, unit="eps", failed=0, source="t"),
        run.make_row(family="critical line", method="gecko::critical_line_at", setting="tolerance 1e-12",
                     input_set="L", n=1000, time_per_call_ns=1200.0, max_err=3e-14, unit="rel", failed=0,
                     source="t"),
        run.make_row(family="batch", method="gecko::critical_line_batch, 1 thread", setting="tolerance 1e-12",
                     input_set="B", n=200, time_per_call_ns=2.5e5, max_err=1e-14, unit="rel", failed=0, source="t",
                     note="4000 designs/s; threads bitwise identical: yes"),
    ]
    run.write_csv(rows, tmp_path / "tradeoff.csv")
    machine = {"cpu": "Test CPU 9000", "logical_cpus": 2, "compiler": "g++ 12.2.0", "flags": "-O3",
               "boost": "1_74", "gsl": "2.7.1", "date_utc": "2026-01-01 00:00 UTC",
               "command": "python3 bench/tradeoff/run.py", "run_time_s": 1.0, "timing": "medians."}
    (tmp_path / "tradeoff.json").write_text(json.dumps({"machine": machine, "rows": rows}))
    (tmp_path / "friction_beam.md").write_text("Rigidity of the beam. Flags: -O3\n\n| a |\n")
    return rows


def test_csv_roundtrip(tmp_path):
    rows = _tiny_results(tmp_path)
    back = run.read_csv(tmp_path / "tradeoff.csv")
    assert [r["method"] for r in back] == [r["method"] for r in rows]
    assert back[1]["max_err"] == 3e4 and back[0]["per"] == "evaluation"


def test_readme_section_replaces_only_between_markers(tmp_path):
    _tiny_results(tmp_path)
    readme = tmp_path / "README.md"
    before = "# title\n\n## Performance\n\n"
    after = "\n\n## Layout\n\nunchanged | text\n"
    readme.write_text(before + readme_section.BEGIN + "\nold numbers 123\n" + readme_section.END + after)
    assert readme_section.update(readme, tmp_path, check=True) is False  # stale
    readme_section.update(readme, tmp_path)
    text = readme.read_text()
    assert text.startswith(before + readme_section.BEGIN + "\n")
    assert text.endswith(readme_section.END + after)
    body = text[text.index(readme_section.BEGIN):text.index(readme_section.END)]
    assert "old numbers 123" not in body
    assert "Test CPU 9000" in body                                    # machine line from the json
    assert "| F | gecko::ellint_f | full | S | 40.0 | 2.00 |" in body  # a row, from the csv
    assert "2.00× " not in body and "(met: 2.00×)" in body            # 80 / 40 against the target 1.5×
    assert "4000 designs/s" in body and "Results bitwise identical on 1 and 2 threads: yes" in body
    assert "bench/results/tradeoff.png" in body
    assert "[`bench/results/friction_beam.md`]" in body and "Rigidity of the beam." in body
    assert readme_section.update(readme, tmp_path, check=True) is True  # now up to date
    readme_section.update(readme, tmp_path)
    assert readme.read_text() == text  # idempotent


def test_readme_section_refuses_bad_markers(tmp_path):
    _tiny_results(tmp_path)
    readme = tmp_path / "README.md"
    readme.write_text("no markers here\n")
    with pytest.raises(ValueError, match="markers"):
        readme_section.update(readme, tmp_path)
    readme.write_text(readme_section.END + "\n" + readme_section.BEGIN + "\n")
    with pytest.raises(ValueError, match="before"):
        readme_section.update(readme, tmp_path)


def test_plot_writes_png(tmp_path):
    pytest.importorskip("matplotlib")
    rows = _tiny_results(tmp_path)
    rows.append(run.make_row(family="F", method="exact", setting="x", input_set="S", time_per_call_ns=100.0,
                             max_err=0.0, unit="eps", failed=0))  # zero error: drawn at a floor, no crash
    run.plot(rows, tmp_path / "t.png")
    assert (tmp_path / "t.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_order_rows_groups_families_then_input_sets():
    mk = lambda fam, s, m: run.make_row(family=fam, method=m, setting="", input_set=s)
    rows = [mk("R_J", "a", "1"), mk("F", "u", "2"), mk("F", "n", "3"), mk("F", "u", "4"), mk("batch", "b", "5"),
            mk("F", "n", "6")]
    assert [r["method"] for r in run.order_rows(rows)] == ["2", "4", "3", "6", "1", "5"]


def test_shuffled_order_repeats_each_input_once_per_block_in_new_orders():
    # n = 7 inputs repeated to 30 elements: four full blocks and two of a fifth; every full block is a
    # permutation of range(n), and no two blocks share their order (a branch predictor would learn it)
    idx = run.shuffled_order(7, 30, seed=3)
    assert idx.shape == (30,)
    blocks = [idx[k * 7:(k + 1) * 7] for k in range(4)]
    for b in blocks:
        assert sorted(b.tolist()) == list(range(7))
    assert len({tuple(b.tolist()) for b in blocks}) == 4
    assert set(idx[28:].tolist()) <= set(range(7))
    # deterministic for a seed, different for another
    assert np.array_equal(idx, run.shuffled_order(7, 30, seed=3))
    assert not np.array_equal(run.shuffled_order(1000, 1000, seed=3), run.shuffled_order(1000, 1000, seed=4))

#!/usr/bin/env python3
"""Regenerates the README's Performance section from the results files (never by hand).

    python3 bench/tradeoff/readme_section.py            # rewrite README.md between the markers
    python3 bench/tradeoff/readme_section.py --check    # exit 1 if README.md is not what the results give
    python3 bench/tradeoff/readme_section.py --print    # print the section only

Only the text strictly between BEGIN and END (below) is replaced; everything else in the README
is left byte for byte. Sources (bench/results/): tradeoff.json/.csv (bench/tradeoff/run.py: the
machine, every family's rows, scipy and the Python rows), elliptic.csv (the own-k column),
seta.csv (bench_seta's critical-line rows), and, when present, scaling.md and the other
benches' .md files, which get a pointer with their own first line (nothing is invented here).
"""
import argparse
import csv
import json
import math
import pathlib
import re
import sys

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent
BEGIN = "<!-- BEGIN GENERATED: bench/tradeoff/readme_section.py (do not edit by hand) -->"
END = "<!-- END GENERATED: bench/tradeoff/readme_section.py -->"

# How the other results files are made (the pointer says which command to run).
COMMANDS = {
    "friction_beam.md": "bench/friction/run.sh",
    "friction_sliding.md": "bench/friction/run.sh",
    "friction_python.md": "python3 bench/friction/bench_steady_sliding.py --out bench/results",
    "scenes.md": "python3 bench/scenes/bench_scenes.py",
    "scaling.md": "bench/scaling/run.sh",
}
RENDERED = {"tradeoff.md", "elliptic.md", "seta.md", "scaling.md"}


def replace_between(text, body):
    """text with everything strictly between the BEGIN and END lines replaced by body."""
    if text.count(BEGIN) != 1 or text.count(END) != 1:
        raise ValueError("README must contain the BEGIN and END markers exactly once each")
    b = text.index(BEGIN) + len(BEGIN)
    e = text.index(END)
    if e < b:
        raise ValueError("README: END marker before BEGIN marker")
    return text[:b] + "\n\n" + body.strip("\n") + "\n" + text[e:]


# ---- formatting -----------------------------------------------------------------------------------
def fnum(v):
    return float(v) if v not in (None, "") else math.nan


def fmt_err(v):
    v = fnum(v)
    if not math.isfinite(v):
        return "—" if math.isnan(v) else "inf"
    if v == 0:
        return "0"
    if v >= 1000 or v < 0.01:
        return f"{v:.1e}"
    return f"{v:.2f}" if v < 10 else f"{v:.1f}"


def fmt_time(v, digits=1):
    v = fnum(v)
    return "—" if not math.isfinite(v) else f"{v:.{digits}f}"


def md(s):
    return str(s).replace("|", "\\|")


def table(header, rows, align):
    out = ["| " + " | ".join(header) + " |", "|" + "|".join(align) + "|"]
    out += ["| " + " | ".join(md(c) for c in r) + " |" for r in rows]
    return "\n".join(out)


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def first_line(path):
    """The first meaningful line of a results file: its title, without the Markdown heading."""
    for line in pathlib.Path(path).read_text().splitlines():
        line = line.strip().lstrip("#").strip()
        if line:
            cut = line.find(". ")  # the first sentence is enough for a pointer
            return line[:cut + 1] if cut > 0 else line
    return ""


def speedup(rows, r, boost_prefix="boost::"):
    """Time of the Boost row of the same family and input set over r's time."""
    for b in rows:
        if b["family"] == r["family"] and b["input_set"] == r["input_set"] and b["method"].startswith(boost_prefix):
            return fnum(b["time_per_call_ns"]) / fnum(r["time_per_call_ns"])
    return math.nan


# ---- sections -------------------------------------------------------------------------------------
def machine_text(m):
    load = " ".join(m.get("load_average", []))
    return (f"Machine: {m.get('cpu', '?')}, {m.get('logical_cpus', '?')} logical CPUs, shared with other jobs "
            f"(load average {load} at the end of the run); {m.get('compiler', 'compiler ?')} "
            f"`{m.get('flags', '?')}`, Boost {m.get('boost', '?')} (policy promote_double<false>), "
            f"GSL {m.get('gsl', '?')}, Python {m.get('python', '?')}, numpy {m.get('numpy', '?')}, "
            f"scipy {m.get('scipy', '?')}. Run on {m.get('date_utc', '?')} by `{m.get('command', '?')}` "
            f"({m.get('run_time_s', '?')} s in all). Timing: {m.get('timing', '')}")


def kernel_rows(rows, families, gecko_settings=("full", "precision<32>")):
    """The subset the README shows: gecko at full and precision<32>, each peer at its default."""
    keep = []
    for r in rows:
        if r["family"] not in families:
            continue
        m, s = r["method"], r["setting"]
        if m.startswith("gecko::") and s not in gecko_settings:
            continue
        if m.startswith("gsl_sf") and s != "GSL_PREC_DOUBLE":
            continue
        if m.endswith("(Python)") or s == "Python scalar call":
            continue  # in tradeoff.csv and the figure; the table keeps one vectorised call per library
        keep.append(r)
    return keep


def elliptic_section(rows, results):
    own = {}
    ep = results / "elliptic.csv"
    if ep.exists():
        fam = {"F(phi|m)": "F", "E(phi|m)": "E", "R_F(x,y,z)": "R_F"}
        for r in read_csv(ep):
            own[(fam.get(r["function"], r["function"]), r["method"], r["setting"], r["input_set"])] = r
    out = []
    heads = [r for r in rows if r["family"] == "F" and r["method"] == "gecko::ellint_f" and r["setting"] == "full"]
    if heads:
        s = [speedup(rows, r) for r in heads]
        met = all(x >= 1.5 for x in s)
        out.append(f"Target: `ellint_f` at full accuracy ≥ 1.5× Boost's `ellint_1` on both input sets "
                   f"({'met' if met else 'NOT met'}: " + " and ".join(f"{x:.2f}×" for x in s) + "); the project's "
                   f"3× goal is {'reached' if all(x >= 3 for x in s) else 'not reached'}.\n")
    body = []
    for r in kernel_rows(rows, ("F", "E", "R_F", "R_D", "R_J")):
        o = own.get((r["family"], r["method"], r["setting"], r["input_set"]))
        own_k = "—"  # scipy, R_D, R_J: no modulus conversion involved
        if r["method"].startswith("gecko::"):
            own_k = "same"
        elif o is not None:
            own_k = fmt_err(o["max_err_eps_own_input"])
        body.append([r["family"], r["method"], r["setting"], r["input_set"], fmt_time(r["time_per_call_ns"]),
                     fmt_err(r["max_err"]), fmt_err(r["rms_err"]), own_k, fmt_time(speedup(rows, r), 2)])
    out.append(table(["function", "method", "setting", "input set", "ns/eval", "max err (eps)", "rms err (eps)",
                      "max err own k (eps)", "speed-up vs Boost"], body,
                     ["---", "---", "---", "---", "--:", "--:", "--:", "--:", "--:"]))
    return "\n".join(out)


def segment_section(rows):
    body = []
    for r in rows:
        if r["family"] != "segment length":
            continue
        if r["method"].startswith("gecko::") and r["setting"] not in ("full", "precision<32>"):
            continue
        body.append([r["method"], r["setting"], r["input_set"].replace("tests/data/seta_solver_segments.csv, ", ""),
                     fmt_time(r["time_per_call_ns"], 0), fmt_err(r["max_err"]), r["failed"]])
    return table(["method", "setting", "segments", "ns/segment", "max err (eps)", "failed"], body,
                 ["---", "---", "---", "--:", "--:", "--:"])


def seta_section(rows):
    body = []
    for r in rows:
        if r["family"] != "critical line":
            continue
        body.append([r["method"], r["setting"], fmt_time(fnum(r["time_per_call_ns"]) / 1e3, 3), fmt_err(r["max_err"]),
                     r["failed"]])
    return table(["method", "setting", "us/point", "max rel. error of Fn", "failed points"], body,
                 ["---", "---", "--:", "--:", "--:"])


def solve_section(rows):
    body = []
    for r in rows:
        if r["family"] != "solve_critical":
            continue
        body.append([r["method"], r["setting"], fmt_time(fnum(r["time_per_call_ns"]) / 1e3, 2), fmt_err(r["max_err"]),
                     r["failed"], r.get("note", "")])
    return table(["method", "setting", "us/state", "max rel. error of Fn", "failed", "note"], body,
                 ["---", "---", "--:", "--:", "--:", "---"])


def batch_text(rows):
    parts = []
    for r in rows:
        if r["family"] != "batch":
            continue
        parts.append(f"{r['method'].replace('gecko::critical_line_batch, ', '')} at {r['setting']}: "
                     f"{1e9 / fnum(r['time_per_call_ns']):.0f} designs/s, max error {fmt_err(r['max_err'])}")
    if not parts:
        return ""
    r0 = next(r for r in rows if r["family"] == "batch")
    ident = "yes" if all("identical: yes" in r.get("note", "") for r in rows if r["family"] == "batch") else "NO"
    status = re.search(r"status: ([^;]*)", r0.get("note", ""))
    checked = re.search(r"(\d+) states checked", r0.get("note", ""))
    return (f"`gecko::critical_line_batch` ({r0['input_set']}, wall time; max error over the "
            f"{checked.group(1) + ' ' if checked else ''}states checked by ODE shooting): "
            + "; ".join(parts) + (f" (status: {status.group(1)})" if status else "")
            + f". Results bitwise identical on 1 and 2 threads: {ident}.")


def scaling_text(results):
    p = results / "scaling.md"
    if not p.exists():
        return ""
    text = p.read_text()
    out = [f"[{first_line(p)}](bench/results/scaling.md) (`{COMMANDS['scaling.md']}`), its lines-per-second "
           "table:\n"]
    m = re.search(r"## Lines per second[^\n]*\n+((?:\|[^\n]*\n)+)", text)
    if m:
        out.append(m.group(1).rstrip("\n"))
    return "\n".join(out)


def pointers(results):
    lines = []
    for p in sorted(results.glob("*.md")):
        if p.name in RENDERED:
            continue
        cmd = COMMANDS.get(p.name)
        lines.append(f"- [`bench/results/{p.name}`](bench/results/{p.name})"
                     + (f" (`{cmd}`)" if cmd else "") + f": {first_line(p)}")
    return "\n".join(lines)


def render(results):
    results = pathlib.Path(results)
    data = json.loads((results / "tradeoff.json").read_text())
    rows, m = data["rows"], data["machine"]
    parts = [machine_text(m),
             f"One command measures everything below in one run: `{m.get('command', 'python3 bench/tradeoff/run.py')}` "
             "(C++ benches built in Release, scipy and the Python rows on the same inputs) → "
             "`bench/results/tradeoff.csv` / `.json`; `bench/tradeoff/README.md` says what each family compares.",
             "![Run time against max error, one panel per family and input set, dashed Pareto front]"
             "(bench/results/tradeoff.png)",
             "### Elliptic kernels\n\nOn the same inputs (20 000 per set for F, E, R_F; 4 000 for R_D, R_J), max and RMS "
             "relative error against mpmath at 40 digits. The peers take the modulus k = √m, precomputed; "
             "\"own k\" is their error at the m' = k² they received (`bench/results/elliptic.md` has every "
             "precision setting and GSL mode, and the error quartiles). scipy and gecko's Python functions are "
             "called once on the whole array (per-element time). Every timed pass or call sees the inputs in a "
             "new order, so that no branch predictor learns the sequence (`bench/harness.hpp`, `visit_order`).",
             elliptic_section(rows, results),
             "### One elastica segment\n\nLength of one elastica segment (docs/theory/two_level_seta.md, the 160 mpmath segments of "
             "`tests/data/seta_solver_segments.csv`, each reference from independent 40-digit quadrature). The "
             "peers integrate the first integral √(EI/2)∫dθ/√R(θ) split at the turning angles, the way a script "
             "would; at a turning point R vanishes and the integrand is singular, which limits them there:",
             segment_section(rows),
             "### Two-level seta\n\nReference scene, 1000-point critical line, natural state and continuation included "
             "(`bench_seta`; gecko and GSL rows checked by an independent long-double RK4 shooting of the ODE; the "
             "Python rows against gecko at tolerance 1e-14):",
             seta_section(rows),
             "One critical state at a given Ft (`solve_critical`), the 403 mpmath states of "
             "`tests/data/seta_reference.csv`, every solver started from the same point 1e-2 away from the "
             "solution (relative in Fn). gecko says in its status when it fails; the GSL peer keeps the Carlson "
             "plan of its starting point (gecko re-plans after convergence), and some of its \"converged\" states "
             "are another root or off the plan, which the note counts:",
             solve_section(rows),
             batch_text(rows),
             scaling_text(results),
             "### Other benchmarks\n\nEach file says how it was made:\n\n" + pointers(results)]
    return "\n\n".join(p for p in parts if p.strip()) + "\n"


def update(readme, results, check=False):
    readme = pathlib.Path(readme)
    old = readme.read_text()
    new = replace_between(old, render(results))
    if check:
        return new == old
    if new != old:
        readme.write_text(new)
    return True


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--readme", type=pathlib.Path, default=ROOT / "README.md")
    ap.add_argument("--results", type=pathlib.Path, default=ROOT / "bench" / "results")
    g = ap.add_mutually_exclusive_group()
    g.add_argument("--check", action="store_true", help="exit 1 if the README section is stale")
    g.add_argument("--print", action="store_true", help="print the generated section")
    args = ap.parse_args(argv)
    if args.print:
        sys.stdout.write(render(args.results))
        return 0
    ok = update(args.readme, args.results, check=args.check)
    if args.check and not ok:
        print(f"{args.readme}: the generated Performance section is stale; run bench/tradeoff/readme_section.py")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())

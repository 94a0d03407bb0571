"""The ``gecko`` command line: validate, plan and run scenes, render the paper figures.

    gecko run SCENE.toml --out DIR [--svg] [--resolution R] [--quiet]
    gecko validate SCENE.toml [...]
    gecko plan SCENE.toml
    gecko figures --out DIR [--only NAME ...] [--list]
    gecko models

Exit status: 0 done, 1 the run failed, 2 bad command line, scene or environment variable,
130 interrupted (EXIT_CODES).
"""
from __future__ import annotations

import argparse
import os
import sys
import time
import warnings
from pathlib import Path
from typing import List, Optional

from ._optional import MissingOptionalDependency

#: the one table of exit statuses, for every command (written out in EPILOG too)
EXIT_OK, EXIT_FAILED, EXIT_USAGE, EXIT_INTERRUPTED = 0, 1, 2, 130
EXIT_CODES = {
    EXIT_OK: "done",
    EXIT_FAILED: "the run failed (a computation, a full disk, another run writing the same sweep)",
    EXIT_USAGE: "bad command line, scene or environment variable, or an output folder that cannot be "
                "created or written to: found before anything is computed",
    EXIT_INTERRUPTED: "interrupted (Ctrl-C): finished sweep work is kept; run the same command to resume",
}

EPILOG = """\
usage of each command (gecko COMMAND --help for details):
  gecko run SCENE.toml --out DIR [--svg] [--resolution R] [--quiet] [--no-figures]
  gecko validate SCENE.toml [SCENE.toml ...]
  gecko plan SCENE.toml [--resolution R]
  gecko figures --out DIR [--only NAME ...] [--svg] [--resolution R] [--quiet]
  gecko figures --list
  gecko models

scenes:
  A scene is a TOML file: [[study]] tables (model, parameters as values, expression strings
  such as "pi/6", lists or {range|logrange = [a, b], num = N} sweeps, combined by "cross" or
  "zip"; outputs such as critical_line, characteristics, shapes) and [[plot]] tables (kind:
  critical_line, characteristic, shapes, sensitivities, force_trace, force_space,
  steady_sliding). A [sweep] section computes characteristics of many designs (a grid, a
  random, Sobol or Latin-hypercube sample over bounds, or a table) into one table, on local
  threads or a Dask cluster (executor = "dask://host:8786"); an [optimize] section maximises
  the pull-off over a box of parameters. See examples/README.md for every key, and
  `gecko models` for the models, their parameters (with the papers' defaults) and outputs.

output:
  `gecko run` writes, for each plot NAME: NAME.png (and NAME.svg with --svg) and NAME.csv with
  every plotted curve (tidy columns: study, curve, label, panel, x, y); for studies with
  `csv = true` in their outputs also SCENE.STUDY.OUTPUT.csv (SCENE: the file's stem); a [sweep]
  NAME.parquet (or NAME.csv) and NAME.png with [sweep.plot]; an [optimize] NAME.json, NAME.csv
  (the optimum's critical line) and NAME.png. Files are written to a staging folder and renamed
  into place only when everything succeeded; an interrupted sweep resumes from its chunks
  (kept in DIR/.gecko-sweep-SCENE.NAME/ until the table is written).

progress:
  A progress bar is shown on a terminal for work that lasts more than a second; nothing
  when stderr is not a terminal, or with --quiet.

limits (checked by validate, plan and run before computing; each an integer >= 1):
  GECKO_MAX_DESIGNS     designs one scene may compute (studies and [sweep]); default 100000000
  GECKO_MAX_MEMORY_MB   estimated memory of its results, MiB; default half the machine's memory
  GECKO_RESOLUTION      default for --resolution: a number in (0, 100]

exit status (every command):
  0    done
  1    the run failed (a computation, a full disk, another run writing the same sweep)
  2    bad command line, scene or environment variable, or an output folder that cannot be
       created or written to: found before anything is computed
  130  interrupted (Ctrl-C): finished sweep work is kept; run the same command to resume

examples:
  gecko run examples/demo_reference_critical_line.toml --out out/
  gecko figures --out figures/ --resolution 0.25
  gecko validate examples/*.toml
"""


def _resolution_arg(text: str) -> float:
    """--resolution and GECKO_RESOLUTION: a number in (0, 100]."""
    try:
        v = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not 0 < v <= 100:  # also refuses nan
        raise argparse.ArgumentTypeError(f"{text!r} is out of range: need a number in (0, 100]")
    return v


def _threads_arg(text: str) -> int:
    try:
        v = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not an integer") from None
    if not 1 <= v <= 4096:
        raise argparse.ArgumentTypeError(f"{text!r} is out of range: need an integer in [1, 4096]")
    return v


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="gecko", formatter_class=argparse.RawDescriptionHelpFormatter, epilog=EPILOG,
        description="Mechanics of gecko-like adhesion: run declarative scenes (TOML) that compute "
                    "critical lines of two-level setae, peel lines, force traces and steady sliding, "
                    "and render the papers' figures.")
    p.add_argument("--version", action="store_true", help="print the version and exit")
    sub = p.add_subparsers(dest="command", metavar="COMMAND")

    def common(sp, out_required: bool):
        sp.add_argument("--out", "-o", metavar="DIR", required=out_required,
                        help="output folder (created if missing)")
        sp.add_argument("--svg", action="store_true", help="also write SVG figures")
        sp.add_argument("--resolution", "-r", type=_resolution_arg, metavar="R",
                        help="scale every range's number of points by R (e.g. 0.25 for a quick look); "
                             "default: the scene's own, or $GECKO_RESOLUTION")
        sp.add_argument("--quiet", "-q", action="store_true", help="no progress bar, no summary")
        sp.add_argument("--threads", type=_threads_arg, metavar="N",
                        help="threads for batch kernels (default: up to 4)")

    r = sub.add_parser("run", help="run a scene: compute, write CSV and figures",
                       description="Run SCENE.toml and write its plots (PNG, SVG on request) and CSV files to DIR.")
    r.add_argument("scene", metavar="SCENE.toml")
    common(r, True)
    r.add_argument("--no-figures", action="store_true", help="write the CSV files only (matplotlib not needed)")

    v = sub.add_parser("validate", help="check scene files without computing",
                       description="Check every key, type and range of each scene; exit 2 at the first bad one.")
    v.add_argument("scenes", metavar="SCENE.toml", nargs="+")

    pl = sub.add_parser("plan", help="show which kernels a scene would run",
                        description="Validate SCENE.toml and print its plan: the kernels the requested outputs need.")
    pl.add_argument("scene", metavar="SCENE.toml")
    pl.add_argument("--resolution", "-r", type=_resolution_arg, metavar="R")

    f = sub.add_parser("figures", help="render every paper figure",
                       description="Render the paper figures (the scenes of examples/, shipped with gecko) to DIR.")
    common(f, False)
    f.add_argument("--only", nargs="+", metavar="NAME", help="only these figure scenes (file stems, e.g. fig2a_axial_stiffness)")
    f.add_argument("--list", action="store_true", help="list the figure scenes and exit")

    sub.add_parser("models", help="list the models, their parameters (defaults) and outputs")
    return p


def _resolution(args) -> Optional[float]:
    if getattr(args, "resolution", None) is not None:
        return args.resolution
    env = os.environ.get("GECKO_RESOLUTION")
    if env is not None and env.strip():
        try:
            return _resolution_arg(env.strip())
        except argparse.ArgumentTypeError as exc:  # the same exit status as a bad --resolution
            from .scene import SceneError
            raise SceneError(str(exc), source="environment variable GECKO_RESOLUTION") from None
    return None


def _err(msg: str) -> None:
    print(f"gecko: error: {msg}", file=sys.stderr)


def _progress(args) -> Optional[bool]:
    return False if args.quiet else None


def main(argv: Optional[List[str]] = None) -> int:
    """Run the ``gecko`` command line: ``gecko run``, ``figures``, ``plan``, ``validate``, ``models``.

    Parameters
    ----------
    argv : list of str, optional
        The arguments (default: ``sys.argv[1:]``).

    Returns
    -------
    int
        The exit status: 0 success, 1 a computation failed, 2 bad usage, an invalid scene or a
        missing optional package (the message names the extra to install), 130 interrupted.

    Examples
    --------
    >>> from gecko.cli import main
    >>> main(["validate", "--help"])  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    SystemExit: 0
    >>> from gecko.scene import figure_scenes
    >>> main(["plan", str(figure_scenes()[0])])  # doctest: +ELLIPSIS
    scene: Two-level seta: critical line of adhesion of the reference design  (resolution 1)
    ...
    0
    """
    with warnings.catch_warnings():
        if not sys.warnoptions:  # the user's -W or PYTHONWARNINGS decide otherwise
            # A deprecated key in a scene is the user's own input: show its warning, which Python's
            # default filters hide because it is raised inside gecko, not in __main__.
            warnings.filterwarnings("default", category=DeprecationWarning, module=r"gecko(\.|$)")
        return _main(argv)


def _main(argv: Optional[List[str]]) -> int:
    os.environ.setdefault("MPLBACKEND", "Agg")  # never open a window
    parser = _parser()
    args = parser.parse_args(argv)
    if args.version:
        from . import __version__
        print(f"gecko {__version__}")
        return 0
    if args.command is None:
        parser.print_help()
        return EXIT_USAGE
    from .scene import SceneError
    try:
        if args.command == "validate":
            from .scene import validate_scene
            for s in args.scenes:
                sc = validate_scene(s, resolution=_resolution(args))
                parts = [f"{len(sc.studies)} studies, {sum(len(x.points) for x in sc.studies)} designs, "
                         f"{len(sc.plots)} plots"]
                if sc.sweep is not None:
                    parts.append(f"a sweep of {sc.sweep.size or 'a table of'} designs")
                if sc.optimize is not None:
                    parts.append(f"an optimize section ({sc.optimize.table['objective']})")
                from .scene.limits import estimate
                parts.append(f"work: {estimate(sc).describe()}")
                print(f"{s}: ok ({', '.join(parts)})")
            return 0
        if args.command == "plan":
            from .scene import load_scene, plan_scene
            print(plan_scene(load_scene(args.scene, resolution=_resolution(args))).describe())
            return 0
        if args.command == "models":
            _print_models()
            return 0
        if args.command == "run":
            return _run([Path(args.scene)], args)
        if args.command == "figures":
            from .scene import figure_scenes
            scenes = figure_scenes()
            if args.list:
                for s in scenes:
                    print(s.stem)
                return 0
            if args.only:
                by = {s.stem: s for s in scenes}
                bad = [n for n in args.only if n not in by]
                if bad:
                    _err(f"unknown figure {bad[0]!r}; figures: " + ", ".join(by))
                    return EXIT_USAGE
                scenes = [by[n] for n in args.only]
            if not args.out:
                _err("figures needs --out DIR")
                return EXIT_USAGE
            return _run(scenes, args)
    except SceneError as err:
        _err(str(err))
        return EXIT_USAGE
    except MissingOptionalDependency as err:  # the message names the extra that installs it
        _err(str(err))
        return EXIT_USAGE
    except KeyboardInterrupt as exc:
        where = ""
        if getattr(exc, "folder", None):  # a sweep: how far it got (gecko._sweep_store.SweepInterrupted)
            where = f" after {exc.done} of {exc.total} sweep designs, which are kept in {exc.folder}"
        _err(f"interrupted{where}; nothing half-written was left in the output folder (a [sweep] keeps its "
             "finished work: run the same command again to resume)")
        return EXIT_INTERRUPTED
    return EXIT_USAGE


def _run(scenes: List[Path], args) -> int:
    from .scene import SceneError, run_scene
    from .scene.runner import Cache
    cache = Cache()  # shared: the figures reuse each other's designs (the reference line ...)
    formats = ["svg"] if args.svg else []
    t0 = time.perf_counter()
    n_files = 0
    for s in scenes:
        try:
            res = run_scene(s, args.out, formats=formats, resolution=_resolution(args),
                            progress=_progress(args), cache=cache, threads=args.threads,
                            draw=not getattr(args, "no_figures", False))
        except (SceneError, MissingOptionalDependency):
            raise
        except Exception as exc:  # a kernel failure: say which scene, exit 1
            _err(f"{s}: {type(exc).__name__}: {exc}")
            return EXIT_FAILED
        n_files += len(res.files)
        if not args.quiet:
            name = s.stem if args.command == "figures" else s
            print(f"{name}: {len(res.files)} files in {res.seconds:.2f} s -> {args.out}")
    if not args.quiet and len(scenes) > 1:
        print(f"{len(scenes)} scenes, {n_files} files in {time.perf_counter() - t0:.2f} s")
    return 0


def _print_models() -> None:
    import math
    from .scene.models import MODELS
    from .scene.schema import _pi_fraction
    for m in MODELS.values():
        print(f"{m.name}: {m.doc}")
        for p in m.params:
            d = p.default
            if isinstance(d, float) and math.isinf(d):
                d = "inf"
            elif p.name.startswith("alpha"):
                d = _pi_fraction(d).replace("π", "pi")
            elif p.kind == "path" or d is None:
                d = d if isinstance(d, str) else "(from preset)"
            print(f"    {p.name:<8} = {d!s:<22} {p.doc}" + (f" [{', '.join(p.choices)}]" if p.choices else ""))
        print(f"  outputs: {', '.join(m.outputs)}")
        if m.characteristics:
            print(f"  characteristics: {', '.join(m.characteristics)}")


if __name__ == "__main__":
    raise SystemExit(main())

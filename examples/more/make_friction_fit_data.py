#!/usr/bin/env python3
"""Writes friction_fit_data.csv, the measured-looking data of friction_fit_measured_data.toml.

The data are SYNTHETIC, not measurements: the paper's viscoelastic Fig 6 model
(gecko.FIG6_VISCOELASTIC, paper 000 eqs 7, 9-10) at 25 speeds from 1 um/s to 10 mm/s, plus
normal noise of 0.5 mN on each force (seed 14), with that sigma in the sigma columns.

    python3 examples/more/make_friction_fit_data.py
"""
from pathlib import Path

import numpy as np

import gecko

SIGMA = 5e-4  # N


def main() -> None:
    V = np.logspace(-6, -2, 25)
    clean = gecko.steady_sliding(V, gecko.FIG6_VISCOELASTIC)
    rng = np.random.default_rng(14)
    F_par = clean.F_par + SIGMA * rng.standard_normal(V.size)
    F_perp = clean.F_perp + SIGMA * rng.standard_normal(V.size)
    lines = ["# synthetic: gecko.FIG6_VISCOELASTIC + 0.5 mN normal noise (seed 14); "
             "written by make_friction_fit_data.py",
             "V,F_par,F_perp,sigma_par,sigma_perp"]
    lines += [f"{v:.6e},{a:.6e},{b:.6e},{SIGMA:g},{SIGMA:g}" for v, a, b in zip(V, F_par, F_perp)]
    (Path(__file__).resolve().parent / "friction_fit_data.csv").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()

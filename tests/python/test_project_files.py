"""The repository is self-contained, findable and citable: checks of the project files.

* no source, test, benchmark or documentation file cites an out-of-tree models note; the theory
  pages they cite exist and define every equation label that is cited;
* nothing under bench/ reads from outside the repository;
* one version everywhere (CMakeLists.txt, CITATION.cff, the package);
* the distribution name, license and extras in pyproject.toml;
* the sdist leaves the benchmark data out (when scikit-build-core is at hand to build one).
"""
import re
import tarfile
from pathlib import Path

import pytest

import gecko

ROOT = Path(__file__).resolve().parents[2]
TEXT = {".hpp", ".cpp", ".h", ".py", ".md", ".toml", ".txt", ".sh", ".cmake", ".in", ".yml", ".cff"}


def _files(*folders):
    for folder in folders:
        for p in (ROOT / folder).rglob("*"):
            if p.is_file() and p.suffix in TEXT and "_build" not in p.parts and "_generated" not in p.parts:
                yield p


def test_no_out_of_tree_models_note_is_cited():
    needle = "models" + ".md"          # spelled apart so that this file does not match itself
    hits = [str(p.relative_to(ROOT)) for p in _files("include", "src", "python", "tests", "bench",
                                                      "examples", "docs", "tools", "cmake")
            if needle in p.read_text(encoding="utf-8", errors="replace")]
    hits += [n for n in ("README.md", "CONTRIBUTING.md", "CHANGELOG.md", "CMakeLists.txt")
             if needle in (ROOT / n).read_text(encoding="utf-8")]
    assert hits == []


def test_the_cited_theory_pages_exist_and_define_the_cited_labels():
    pages = {"two_level_seta": ROOT / "docs/theory/two_level_seta.md",
             "frictional_adhesion": ROOT / "docs/theory/frictional_adhesion.md"}
    labels = set()
    for page in pages.values():
        assert page.exists(), page
        labels |= set(re.findall(r"^\$\$ \(([a-z0-9-]+)\)$", page.read_text(encoding="utf-8"), re.M))
    assert {"seta-eq-15", "seta-eq-1", "seta-eq-17", "friction-eq-9", "friction-eq-1"} <= labels
    cited = set()
    for p in _files("include", "python", "docs"):
        cited |= set(re.findall(r"\b((?:seta|friction)-eq-[a-z0-9-]*[a-z0-9])\b", p.read_text(encoding="utf-8")))
    assert cited <= labels, sorted(cited - labels)


def test_benchmarks_read_nothing_from_outside_the_repository():
    bad = [str(p.relative_to(ROOT)) for p in _files("bench", "validation")
           if re.search(r"\.\./shared|/work/|ROOT\.parent|\.\./\.\./\.\.", p.read_text(encoding="utf-8"))]
    assert bad == []
    assert (ROOT / "bench/seta/scipy_peer.py").exists()


def test_one_version_everywhere():
    cmake = re.search(r"project\(gecko VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text()).group(1)
    cff = re.search(r"^version: ([0-9.]+)$", (ROOT / "CITATION.cff").read_text(), re.M).group(1)
    assert cmake == cff == gecko.__version__


def test_citation_file_cites_the_software_and_both_papers():
    yaml = pytest.importorskip("yaml")
    cff = yaml.safe_load((ROOT / "CITATION.cff").read_text(encoding="utf-8"))
    assert cff["cff-version"] == "1.2.0" and cff["type"] == "software"
    assert cff["license"] == "MIT"
    refs = cff["references"]
    assert len(refs) == 2
    assert any(r.get("doi") == "10.1021/jp8067415" for r in refs)
    assert any("two-level seta" in r["title"] for r in refs)


def test_pyproject_metadata():
    tomllib = pytest.importorskip("tomllib")
    meta = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    assert meta["name"] == "gecko-adhesion"
    assert meta["license"] == "MIT" and (ROOT / "LICENSE").read_text().startswith("MIT License")
    assert meta["scripts"] == {"gecko": "gecko.cli:main"}
    assert {"plot", "sweep", "dask", "optimize", "test", "docs"} <= set(meta["optional-dependencies"])
    assert meta["authors"] and meta["urls"] and meta["classifiers"]
    for v in ("3.9", "3.10", "3.11", "3.12", "3.13"):
        assert f"Programming Language :: Python :: {v}" in meta["classifiers"]


def test_sdist_leaves_out_the_benchmark_data(tmp_path, monkeypatch):
    build = pytest.importorskip("scikit_build_core.build")
    monkeypatch.chdir(ROOT)
    name = build.build_sdist(str(tmp_path))
    archive = tmp_path / name
    with tarfile.open(archive) as tar:
        members = tar.getnames()
    assert not [m for m in members if re.search(r"/bench/results/|/bench/.*/data/|/validation/(data|results)/|\.npz$|\.bin$|_chunks/", m)]
    for needed in ("CMakeLists.txt", "pyproject.toml", "include/gecko/gecko.hpp", "python/gecko/__init__.py",
                   "src/bindings", "cmake/gecko-config.cmake.in", "LICENSE", "bench/seta/scipy_peer.py"):
        assert any(m.split("/", 1)[-1].startswith(needed) for m in members), needed
    assert archive.stat().st_size < 2_000_000

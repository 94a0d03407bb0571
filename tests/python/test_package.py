"""The package itself: version from the build, the public names of the design contract, stubs."""
import pathlib
import re

import gecko

ROOT = pathlib.Path(__file__).resolve().parents[2]


def test_version_comes_from_the_cmake_project():
    cmake = (ROOT / "CMakeLists.txt").read_text()
    assert gecko.__version__ == re.search(r"project\(gecko VERSION ([0-9.]+)", cmake).group(1)


def test_all_lists_only_existing_public_names():
    assert len(gecko.__all__) == len(set(gecko.__all__))
    for name in gecko.__all__:
        assert hasattr(gecko, name), name


def test_contract_names_of_design_md():
    for name in ["ellint_f", "ellint_e", "ellint_k", "ellint_ek",
                 "carlson_rf", "carlson_rd", "carlson_rj", "carlson_rc"]:
        assert name in gecko.__all__, name


def test_compiled_module_ships_its_stub():
    pkg = pathlib.Path(gecko.__file__).parent
    stub = (pkg / "_core.pyi").read_text()
    for name in dir(gecko._core):
        if not name.startswith("_"):
            assert f"def {name}(" in stub or f"class {name}" in stub or f"{name}:" in stub, name

"""When scripts/test.sh runs pytest in the venv the wheel was installed into
(FLEXURE_EXPECT_INSTALLED=venv), the module under test must be the installed one."""
import os

import pytest

import flexure


def test_the_module_under_test_is_the_installed_wheel():
    venv = os.environ.get("FLEXURE_EXPECT_INSTALLED")
    if not venv:
        pytest.skip("not the installed-wheel run (scripts/test.sh sets FLEXURE_EXPECT_INSTALLED)")
    assert os.path.realpath(flexure.__file__).startswith(os.path.realpath(venv))
    assert "site-packages" in flexure.__file__
    assert os.path.exists(os.path.join(os.path.dirname(flexure.__file__), "__init__.pyi"))
    assert flexure.beam(alpha2=2.0)["converged"]

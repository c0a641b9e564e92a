"""Shared set-up of the Python tests: the package from the build tree (PYTHONPATH set by
ctest), the CLI next to it and CONTACT's examples."""

import os
import pathlib

import pytest

CLI = os.environ.get("ROLLCONTACT_CLI", "")
EXAMPLES = pathlib.Path(os.environ.get("ROLLCONTACT_EXAMPLES_DIR", "/nonexistent"))
REPO_EXAMPLES = pathlib.Path(__file__).resolve().parents[2] / "examples"


@pytest.fixture
def cli():
    if not CLI or not os.path.exists(CLI):
        pytest.skip("ROLLCONTACT_CLI not set")
    return CLI

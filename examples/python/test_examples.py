"""Runs every numbered Python example (run by ctest through pytest): each must finish and write
its picture."""
import glob
import os
import runpy
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(os.environ.get("COVERKIT_SOURCE_DIR", os.path.join(HERE, "..", "..")), "datasets", "data")
EXAMPLES = sorted(glob.glob(os.path.join(HERE, "[0-9][0-9]_*.py")))


def test_there_are_five_examples():
    assert [os.path.basename(e)[:2] for e in EXAMPLES] == ["01", "02", "03", "04", "05"]


@pytest.mark.parametrize("script", EXAMPLES, ids=[os.path.basename(e) for e in EXAMPLES])
def test_example_runs_and_draws(script, tmp_path, monkeypatch):
    monkeypatch.setattr(sys, "argv", [script, DATA, str(tmp_path)])
    runpy.run_path(script, run_name="__main__")
    pictures = [p for p in os.listdir(tmp_path) if p.endswith((".png", ".svg"))]
    assert pictures, os.listdir(tmp_path)
    for p in pictures:
        assert os.path.getsize(tmp_path / p) > 100

"""The tutorial's code runs as written (docs/tutorial/07-python.md), in a scratch folder that
holds the repository's worlds and examples as a clone does."""

import os
import re

import matplotlib.image

from conftest import ROOT

TUTORIAL = ROOT / "docs" / "tutorial" / "07-python.md"


def code_blocks(markdown: str) -> list[str]:
    return re.findall(r"^```python\n(.*?)^```", markdown, flags=re.S | re.M)


def test_the_tutorial_runs_and_draws_its_figure(tmp_path, monkeypatch):
    for folder in ("worlds", "examples"):
        os.symlink(ROOT / folder, tmp_path / folder)
    monkeypatch.chdir(tmp_path)
    blocks = code_blocks(TUTORIAL.read_text())
    assert len(blocks) >= 4
    namespace = {"__name__": "tutorial"}
    for block in blocks:
        exec(compile(block, str(TUTORIAL), "exec"), namespace)
    figure = matplotlib.image.imread(tmp_path / "noa.png")
    assert figure.shape[0] > 100 and figure.shape[1] > 100
    assert 0.5 < namespace["a"] < 3 and 0 < namespace["b"] < 1.5

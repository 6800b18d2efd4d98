"""The examples of docs/python.md run and reach their answers."""

import runpy
from pathlib import Path

import pytest

EXAMPLES = sorted((Path(__file__).resolve().parents[1] / "examples").glob("*.py"))


@pytest.mark.parametrize("path", EXAMPLES, ids=[p.stem for p in EXAMPLES])
def test_example_runs(path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    runpy.run_path(str(path), run_name="__main__")
    assert capsys.readouterr().out


@pytest.mark.parametrize("path", EXAMPLES, ids=[p.stem for p in EXAMPLES])
def test_docs_show_the_example_as_it_is(path: Path) -> None:
    docs = (Path(__file__).resolve().parents[3] / "docs" / "python.md").read_text()
    assert path.read_text() in docs, f"docs/python.md shows an old {path.name}"

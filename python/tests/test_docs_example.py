"""The example in docs/python.md runs as written (cell by cell, from the repository root)."""
import os
import re

from conftest import SOURCE_DIR


def test_docs_example_runs(tmp_path, monkeypatch, capsys):
    text = (SOURCE_DIR / "docs/python.md").read_text()
    cells = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    assert len(cells) >= 4
    # The example reads scenes/ and writes its pictures into the working directory.
    os.symlink(SOURCE_DIR / "scenes", tmp_path / "scenes")
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    namespace = {}
    for cell in cells:
        exec(compile(cell, "docs/python.md", "exec"), namespace)
    assert (tmp_path / "penumbra-hrc.png").stat().st_size > 0
    assert (tmp_path / "block.png").stat().st_size > 0
    printed = capsys.readouterr().out
    assert "rel_l1" in printed and "100.0%" in printed
    # The HRC the example shows is close to its reference.
    assert namespace["luxel"].compare(namespace["hrc"], namespace["reference"])["rel_l1"] < 0.05

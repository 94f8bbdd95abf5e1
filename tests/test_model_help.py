"""Every ``--model`` help text names every kinematic model (m5 was missing from five)."""

import pytest

from birdsim.cli import main
from birdsim.physics.kinematics import MODELS


@pytest.mark.parametrize(
    "command", [["fly"], ["render"], ["forces"], ["envelope"], ["tables", "build"]]
)
def test_model_help_lists_every_model(command, capsys):
    with pytest.raises(SystemExit):
        main([*command, "--help"])
    text = " ".join(capsys.readouterr().out.split())
    for name in MODELS:
        assert f"{name}," in text or f"{name} " in text, (command, name)
    assert "m4 or m5" in text

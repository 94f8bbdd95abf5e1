import json
import math

from birdsim.cli import main
from birdsim.commands.params import reference
from birdsim.physics.examples import EXAMPLES
from birdsim.physics.kinematics import MODELS


def test_every_parameter_of_every_model_is_listed_with_its_examples():
    ref = reference()
    assert list(ref) == list(MODELS)
    for name, km in MODELS.items():
        rows = {p["name"]: p for p in ref[name]["params"]}
        assert list(rows) == list(km.param_names)
        for spec in km.params:
            row = rows[spec.name]
            assert (row["lower"], row["upper"], row["unit"]) == (spec.lower, spec.upper, "rad")
            assert (
                row["meaning"] == spec.doc and row["lower"] <= row["default_cruise"] <= row["upper"]
            )
        for ex in (e for e in EXAMPLES if e.model == name):
            for p, v in ex.params.items():
                assert rows[p]["examples"][f"eq{ex.equation} {ex.regime} (V={ex.speed:g})"] == v


def test_cli_params(capsys):
    assert main(["params", "m4", "--json"]) == 0
    assert list(json.loads(capsys.readouterr().out)) == ["m4"]
    assert main(["params", "m3"]) == 0
    out = capsys.readouterr().out
    assert "stroke_plane" in out and "eq75" in out and "pi/4" in out
    assert main(["params", "m9"]) == 2
    err = capsys.readouterr().err
    assert "m9" in err and err.count("\n") == 1
    assert math.isclose(reference("m4")["m4"]["params"][1]["upper"], math.pi / 4)

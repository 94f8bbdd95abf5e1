"""commands/common.py: the library's Python argument names become the user's flags."""

from __future__ import annotations

import pytest

from birdsim.commands.common import flag_names, translate
from birdsim.errors import BirdConfigError, BirdsimError


def test_translate_maps_the_leading_name_once_and_the_hints_everywhere() -> None:
    starts = {"speed=": "--speed=", "model ": "--model "}
    assert translate("speed=nan is invalid", starts) == "--speed=nan is invalid"
    assert translate("model 'm9' is unknown", starts) == "--model 'm9' is unknown"
    # only the start: a name inside the message is the library's own wording
    assert translate("a speed=1 example", starts) == "a speed=1 example"
    assert translate(
        "V=5 is outside; allowed: [0, 1] (or clip=True)", {"V=": "--V="}, {"clip=True": "--clip"}
    ) == ("--V=5 is outside; allowed: [0, 1] (or --clip)")


def test_flag_names_rewrites_the_error_and_keeps_its_type() -> None:
    with pytest.raises(BirdConfigError) as info:
        with flag_names({"path=": "--bird "}):
            raise BirdConfigError("path='x.toml' does not exist")
    assert str(info.value) == "--bird 'x.toml' does not exist"
    with pytest.raises(KeyError):  # not a user's mistake: untouched
        with flag_names({"path=": "--bird "}):
            raise KeyError("path=")
    with flag_names({}):
        pass
    assert issubclass(BirdConfigError, BirdsimError)

"""The flown-prediction gates a free flight builds (``flown_pitch``, ``flown_lateral``),
captured for the tests that fly them."""

from __future__ import annotations

from types import ModuleType

from birdsim.flight import freeflight


def capture_gate(monkeypatch, module: ModuleType, factory: str, enabled: bool = True) -> list:
    """The list that collects every gate ``freeflight.<factory>`` makes (None where the
    flight builds none); ``enabled`` False switches ``module.ENABLED`` off first."""
    made: list = []
    make = getattr(freeflight, factory)

    def capture(*a):
        made.append(make(*a))
        return made[-1]

    if not enabled:  # else the module as shipped
        monkeypatch.setattr(module, "ENABLED", False)
    monkeypatch.setattr(freeflight, factory, capture)
    return made

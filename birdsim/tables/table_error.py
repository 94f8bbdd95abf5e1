"""The error of the lookup tables: a table file that cannot be read, or a lookup it
cannot answer (its own module, so that every table module can raise it without
importing :mod:`birdsim.tables.lookup`)."""

from __future__ import annotations

from birdsim.errors import BirdsimError


class TableError(BirdsimError):
    """A table file that cannot be read, or a lookup it cannot answer."""

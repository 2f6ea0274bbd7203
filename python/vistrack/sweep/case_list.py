"""A sweep's cases as a lazy sequence: each case (the base with its values set, a deep copy) is
built when it is asked for, so a sweep of 10^6 allowed cases holds one case's data at a time, not
a copy of the base per case."""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Iterator, Sequence
from typing import Any, Generic, TypeVar, overload

T = TypeVar("T")


class CaseList(Sequence[T], Generic[T]):
    """The cases of the parameter ``columns`` in index order (grid: the last parameter varies
    fastest; zip: the i-th value of every parameter), each made by ``build(index, values)``."""

    def __init__(self, columns: Sequence[Sequence[Any]], combine: str,
                 build: Callable[[int, tuple[Any, ...]], T]) -> None:
        self._columns = [list(c) for c in columns]
        self._grid = combine == "grid"
        self._build = build
        lengths = [len(c) for c in self._columns]
        self._count = math.prod(lengths) if self._grid else (lengths[0] if lengths else 0)

    def __len__(self) -> int:
        return self._count

    @overload
    def __getitem__(self, index: int) -> T: ...

    @overload
    def __getitem__(self, index: slice) -> list[T]: ...

    def __getitem__(self, index: int | slice) -> T | list[T]:
        if isinstance(index, slice):
            return [self[i] for i in range(*index.indices(self._count))]
        if index < 0:
            index += self._count
        if not 0 <= index < self._count:
            raise IndexError(f"case {index}: the sweep has {self._count} cases")
        return self._build(index, self._values(index))

    def __iter__(self) -> Iterator[T]:
        rows = itertools.product(*self._columns) if self._grid else zip(*self._columns)
        for index, values in enumerate(rows):
            yield self._build(index, tuple(values))

    def _values(self, index: int) -> tuple[Any, ...]:
        if not self._grid:
            return tuple(column[index] for column in self._columns)
        values = []
        for column in reversed(self._columns):  # mixed radix, the last parameter fastest
            index, digit = divmod(index, len(column))
            values.append(column[digit])
        return tuple(reversed(values))

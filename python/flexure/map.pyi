from typing import Any, Callable

def cfm(
    *,
    config: str,
    R: float | str,
    d: float | str,
    out: str,
    K1: float | str | None = ...,
    K2: float | str | None = ...,
    model: str | None = ...,
    exact_points: int | None = ...,
    progress: Callable[[int, int], object] | None = ...,
) -> dict[str, Any]: ...

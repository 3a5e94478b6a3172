from typing import Any

def cfm(
    *,
    config: str,
    d: float,
    objective: str,
    pcf_min: float | None = ...,
    orientation: str | None = ...,
    K1: float | None = ...,
    K2: float | None = ...,
    sampling: str | None = ...,
    points: int | None = ...,
    starts: int | None = ...,
    seed: int | None = ...,
) -> dict[str, Any]: ...

def mechanism(
    *,
    force: float | str,
    stroke: float | str,
    E: float | str,
    safety_factor: float,
    length_range: float | str | tuple[float | str, float | str],
    width_range: float | str | tuple[float | str, float | str],
    thickness_range: float | str | tuple[float | str, float | str],
    yield_strength: float | str | None = ...,
    in_plane: bool = ...,
    out_of_plane: bool = ...,
    pcf_min: float | None = ...,
    config: str | list[str] | None = ...,
    rank: str | None = ...,
    force_of: str | None = ...,
    exact: bool = ...,
    model: str | None = ...,
    points: int | None = ...,
    out: str | None = ...,
) -> dict[str, Any]: ...

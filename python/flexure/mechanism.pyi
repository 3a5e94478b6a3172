import os
from typing import Any, Callable, Union

Design = Union[str, os.PathLike[str], dict[str, Any]]

def list() -> dict[str, Any]: ...
def analyze(
    mechanism: Design,
    *,
    points: int | None = ...,
    method: str | None = ...,
    tol: float | None = ...,
    out: str | os.PathLike[str] | None = ...,
    prbm_only: bool = ...,
    spring_rule: str | None = ...,
    force_of: str | None = ...,
    material: str | None = ...,
    surface_finish: str | None = ...,
    reliability: float | None = ...,
    Kf: float | None = ...,
    fatigue_factor: float | None = ...,
    ultimate_strength: str | float | None = ...,
    endurance_limit: str | float | None = ...,
    plate: str | None = ...,
    nu: float | None = ...,
    stable: bool = ...,
    model: str | None = ...,
    flexure_models: str | dict[str, str] | None = ...,
    flexure_tol: float | None = ...,
    check_flexures: bool = ...,
    input: str | None = ...,
    progress: Callable[[int, int], object] | None = ...,
) -> dict[str, Any]: ...
def tolerance(
    mechanism: Design,
    *,
    thickness: str | float | None = ...,
    width: str | float | None = ...,
    length: str | float | None = ...,
    E: str | float | None = ...,
    samples: int | None = ...,
    distribution: str | None = ...,
    seed: int | None = ...,
    method: str | None = ...,
    points: int | None = ...,
    out: str | os.PathLike[str] | None = ...,
) -> dict[str, Any]: ...
def validate(
    *,
    designs: str | None = ...,
    points: int | None = ...,
    toggle_fraction: float | None = ...,
    spring_rule: str | None = ...,
    spring_rules: bool = ...,
) -> dict[str, Any]: ...

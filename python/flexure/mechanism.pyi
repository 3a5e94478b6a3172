import os
from typing import Any, Union

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
) -> dict[str, Any]: ...
def validate(
    *,
    designs: str | None = ...,
    points: int | None = ...,
    toggle_fraction: float | None = ...,
    spring_rule: str | None = ...,
    spring_rules: bool = ...,
) -> dict[str, Any]: ...

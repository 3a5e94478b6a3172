from typing import Any

def derive(
    *,
    segment: str | None = ...,
    kappa0: float | None = ...,
    n: float | None = ...,
    step: float | None = ...,
    theta_max_K: float | None = ...,
    tail: int | None = ...,
) -> dict[str, Any]: ...
def table(
    *,
    segment: str | None = ...,
    step: float | None = ...,
    tail: int | None = ...,
    n_min: float | None = ...,
    n_max: float | None = ...,
    n_steps: int | None = ...,
) -> dict[str, Any]: ...
def compare(
    *,
    segment: str | None = ...,
    n: float | None = ...,
    alpha2: float | None = ...,
    mu: float | None = ...,
    constants: str | None = ...,
    range: str | None = ...,
) -> dict[str, Any]: ...

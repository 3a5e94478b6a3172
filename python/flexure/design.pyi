from typing import Any

def cfm(
    *,
    config: str,
    d: float,
    objective: str,
    pcf_min: float | None = ...,
    orientation: str | None = ...,
    rule_limits: str | None = ...,
    K1: float | None = ...,
    K2: float | None = ...,
    sampling: str | None = ...,
    points: int | None = ...,
    starts: int | None = ...,
    scan_points: int | None = ...,
    coarse_stride: int | None = ...,
    seed: int | None = ...,
) -> dict[str, Any]: ...

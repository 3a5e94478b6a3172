#pragma once
// flexure's files in one include: segment chains and mechanisms read from (and written to) TOML,
// general mechanisms from TOML, and drawings of a mechanism (SVG, DXF). Link `flexure::io` (or
// `flexure::flexure`). The studies of `flexure validate`, `bench` and `sweep` (benchmarks/studies)
// are not public: their results reach users through the command line and Python.
#include "flexure/io/mechanism_drawing.h"
#include "flexure/io/toml_files.h"
#include "flexure/mechanisms.h"

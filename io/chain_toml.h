#pragma once
// Reads a segment chain (solver/chain_model/segment_chain.h) from a TOML file, for
// `flexure beam --chain FILE.toml` and `flexure path --chain FILE.toml`. Format:
// docs/chain-toml.md; examples in docs/examples/. Unknown keys, missing values and wrong types are
// InvalidInput errors that name the file, the key and its line.
#include <string>

#include "flexure/solver/chain_model/segment_chain.h"

namespace flexure::io {

SegmentChain read_chain_toml(const std::string& path);
// The same from TOML text; `source_name` is used in messages.
SegmentChain parse_chain_toml(const std::string& text, const std::string& source_name);

}  // namespace flexure::io

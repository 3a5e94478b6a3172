#pragma once
// The HDF5 file of a contact solution (`flexure beam --chain FILE --out FILE.h5` with a
// [[contact]]; layout in docs/hdf5-schema.md "beam with contact"): the contact region, forces and
// separation points, the tip and clamp reaction, the landing and lift-off events, the
// continuation path and (on request) the shape. Written whole or not at all (AtomicHdf5File).
#include <string>

#include "flexure/solver/shooting/rigid_contact.h"

namespace flexure::io {

// `physical`: the values are SI (m, N, N m, N/m); else consistent units ("1").
void write_contact_hdf5(const std::string& path, const ContactResult& result, bool physical);

}  // namespace flexure::io

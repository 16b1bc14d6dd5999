// collide.pair_correlation, collide.local_psi6 and collide.psi6: the structure of a
// configuration as core/structure computes it for the samplers and the run record (g(r) near
// contact with its contact value; the bond-orientational order psi6), bound for the course's
// figures and checkers and for notebooks (docs/python.md, "Structure"). No second implementation.
#pragma once

#include <pybind11/pybind11.h>

namespace collide::python {

void bind_structure(pybind11::module_& m);

}  // namespace collide::python

// Opening a run in other programs (docs/exporting.md): the frames of a run file written with
// `--frames`, described for the tools that read particle trajectories.
//
//   xdmf  an XDMF 3 file: XML that points into the run file (nothing copied), read by ParaView
//         and VisIt as a time series of points with radius, mass and velocity (x, y)
//   xyz   extended XYZ text, one block per frame (ASE, OVITO); every number printed in the
//         shortest form that reads back as the same double
//   gsd   HOOMD's GSD (OVITO, freud, HOOMD): written by python/collide/gsd_export.py with the
//         `gsd` package, since Debian has no GSD library for C++
#pragma once

#include <string>

namespace collide {

enum class ExportFormat { xdmf, xyz, gsd };

// "xdmf", "xyz", "gsd"; or, for an empty `name`, the extension of `out` (.xdmf/.xmf, .xyz,
// .gsd). Throws std::runtime_error naming the choices otherwise.
ExportFormat export_format(const std::string& name, const std::string& out);
const char* to_string(ExportFormat f);

// Throws std::runtime_error naming the file when it is no run file, or one without frames (the
// message names --frames).
void require_frames(const std::string& run_path);

// The XDMF document for `run_path`, to be written at `xdmf_path`: it names the run file by its
// path relative to the XDMF file's folder, so the two can be moved together.
std::string xdmf_text(const std::string& run_path, const std::string& xdmf_path);

// The extended XYZ text of every frame of `run_path` (held in memory: for large runs use GSD
// or XDMF).
std::string xyz_text(const std::string& run_path);

}  // namespace collide

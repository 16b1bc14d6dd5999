// Opening a run in other programs (docs/exporting.md): the frames of a run file written with
// `--frames`, described for the tools that read particle trajectories.
//
//   xdmf  an XDMF 3 file and its data beside it (NAME.frames.h5: plain per-frame datasets),
//         read by ParaView (Xdmf3 readers), VisIt and meshio as a time series of points with
//         radius, mass and velocity
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

// Writes the XDMF document `xdmf_path` and, beside it, its data: xdmf_frames_path(xdmf_path),
// an HDF5 file of plain per-frame datasets (/frames/K/position and /frames/K/velocity, N x 3
// with z = 0; /particles/radius, mass and vertex). Every DataItem names a whole dataset of that
// file by its name alone, so the two files move together. Both go through the output guard and
// are renamed into place (the data file first); throws naming the file otherwise.
void write_xdmf(const std::string& run_path, const std::string& xdmf_path);
// DIR/NAME.xdmf -> DIR/NAME.frames.h5 (for a symbolic link: beside the file it points to).
std::string xdmf_frames_path(const std::string& xdmf_path);

// The extended XYZ text of every frame of `run_path` (held in memory: for large runs use GSD
// or XDMF).
std::string xyz_text(const std::string& run_path);

}  // namespace collide

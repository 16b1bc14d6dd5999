# Draws the last frame of an XDMF export in ParaView without a window, as in
# docs/exporting.md:
#
#   collide run data/scenes/bidisperse_gas.toml --backend event --frames --out run.h5
#   collide export run.h5 --out run.xdmf
#   xvfb-run -a pvbatch docs/figures/paraview_screenshot.py run.xdmf paraview_bidisperse_gas.png
#
# ParaView (Debian's paraview and python3-paraview) is not a dependency of collide, so the
# tests do not run this (they read the export with meshio's TimeSeriesReader).
#
# The reader is ParaView's Xdmf3 reader: the export's data items name whole datasets of
# NAME.frames.h5 (no HyperSlab, on which ParaView 5.11's Xdmf3 readers crashed), and the
# velocity is a 3-vector with z = 0.
import os
import sys

from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetColorTransferFunction, GetScalarBar, Glyph,
                             ResetCamera, SaveScreenshot, Show, Xdmf3ReaderS)

# An absolute path: ParaView 5.11's Xdmf3 readers join a bare file name ("run.xdmf") and the
# data file's relative name into "run.xdmfrun.frames.h5" and abort; "./run.xdmf" works.
xdmf_path, png_path = os.path.abspath(sys.argv[1]), sys.argv[2]
run = Xdmf3ReaderS(FileName=[xdmf_path])
# A sphere per disk, scaled to its diameter (the glyph's unit sphere has diameter 1).
disks = Glyph(Input=run, GlyphType="Sphere", ScaleArray=["POINTS", "radius"], ScaleFactor=2.0,
              GlyphMode="All Points")
view = GetActiveViewOrCreate("RenderView")
display = Show(disks, view)
ColorBy(display, ("POINTS", "velocity", "Magnitude"))
display.SetScalarBarVisibility(view, True)
bar = GetScalarBar(GetColorTransferFunction("velocity"), view)
bar.Title, bar.ComponentTitle, bar.RangeLabelFormat = "speed", "", "%-#.2f"
# A square picture, the colour bar below the box.
bar.Orientation, bar.WindowLocation = "Horizontal", "Any Location"
bar.Position, bar.ScalarBarLength = [0.2, 0.02], 0.6
view.InteractionMode = "2D"
view.OrientationAxesVisibility = 0
ResetCamera()
# Zoom out a little and move the box up, to leave the bottom sixth to the bar.
view.CameraParallelScale *= 1.15
for key in ("CameraPosition", "CameraFocalPoint"):
    point = list(getattr(view, key))
    point[1] -= 0.15 * view.CameraParallelScale
    setattr(view, key, point)
view.ViewTime = run.TimestepValues[-1]
SaveScreenshot(png_path, view, ImageResolution=[600, 600], CompressionLevel="9")

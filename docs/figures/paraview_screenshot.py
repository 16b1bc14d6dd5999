# Draws the last frame of an XDMF export in ParaView without a window, as in
# docs/exporting.md:
#
#   collide run data/scenes/bidisperse_gas.toml --backend event --frames --out run.h5
#   collide export run.h5 --out run.xdmf
#   xvfb-run -a pvbatch docs/figures/paraview_screenshot.py run.xdmf paraview_bidisperse_gas.png
#
# ParaView (Debian's paraview and python3-paraview) is not a dependency of collide, so the
# tests do not run this; the figure in docs/figures was made with ParaView 5.11.
#
# The reader is ParaView's "XDMF Reader": ParaView 5.11's Xdmf3 readers stop with a
# segmentation fault on any geometry given as a HyperSlab of a larger dataset, which is how
# the export points at one frame of /frames/position without copying it.
import sys

from paraview.simple import (Calculator, ColorBy, GetActiveViewOrCreate, GetColorTransferFunction, GetScalarBar, Glyph,
                             ResetCamera, SaveScreenshot, Show, XDMFReader)

xdmf_path, png_path = sys.argv[1], sys.argv[2]
run = XDMFReader(FileNames=[xdmf_path])
# The run file stores velocity as (x, y); ParaView's vectors have three components.
velocity = Calculator(Input=run, ResultArrayName="velocity", Function="velocity_x*iHat + velocity_y*jHat")
# A sphere per disk, scaled to its diameter (the glyph's unit sphere has diameter 1).
disks = Glyph(Input=velocity, GlyphType="Sphere", ScaleArray=["POINTS", "radius"], ScaleFactor=2.0,
              GlyphMode="All Points")
view = GetActiveViewOrCreate("RenderView")
display = Show(disks, view)
ColorBy(display, ("POINTS", "velocity", "Magnitude"))
display.SetScalarBarVisibility(view, True)
bar = GetScalarBar(GetColorTransferFunction("velocity"), view)
bar.Title, bar.ComponentTitle, bar.RangeLabelFormat = "speed", "", "%-#.2f"
bar.WindowLocation, bar.Position, bar.ScalarBarLength = "Any Location", [0.76, 0.2], 0.6
view.InteractionMode = "2D"
ResetCamera()
view.ViewTime = run.TimestepValues[-1]
SaveScreenshot(png_path, view, ImageResolution=[960, 540])

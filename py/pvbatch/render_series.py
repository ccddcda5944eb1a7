"""Render the last snapshot of a run's ParaView series to a PNG, headless, with ParaView itself:
discs as circles coloured by displacement, intact bonds grey, cracks red (tension) and blue
(shear), joints by set. A pvbatch script (ParaView's Python), not a module of the package:

    source scripts/env.sh
    PYTHONPATH=$TOPPLING_PARAVIEW_PYTHON xvfb-run -a pvbatch py/pvbatch/render_series.py results/tilting_table/demo/paraview picture.png
"""
import os
import sys

from paraview import simple as pv

WIDTH, HEIGHT = 1200, 800


def show_discs(folder: str, view):
    discs = pv.PVDReader(FileName=os.path.join(folder, "discs.pvd"))
    glyphs = pv.Glyph(Input=discs, GlyphType="Sphere")
    glyphs.ScaleArray = ["POINTS", "radius"]
    glyphs.ScaleFactor = 2.0  # a unit sphere's diameter is 1: scaled by twice the radius
    glyphs.GlyphMode = "All Points"
    display = pv.Show(glyphs, view)
    pv.ColorBy(display, ("POINTS", "displacement", "Magnitude"))
    display.RescaleTransferFunctionToDataRange(True, False)
    display.SetScalarBarVisibility(view, True)


def show_lines(folder: str, kind: str, view, colour=None, by=None, width=1.0):
    source = pv.PVDReader(FileName=os.path.join(folder, f"{kind}.pvd"))
    display = pv.Show(source, view)
    display.LineWidth = width
    if by:
        pv.ColorBy(display, ("CELLS", by))
    else:
        display.ColorArrayName = ["POINTS", ""]  # one colour
        display.AmbientColor = display.DiffuseColor = colour
    return display


def main(folder: str, png: str) -> None:
    view = pv.CreateView("RenderView")
    view.ViewSize = [WIDTH, HEIGHT]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [1, 1, 1]
    show_discs(folder, view)
    show_lines(folder, "bonds", view, colour=[0.6, 0.6, 0.6])
    show_lines(folder, "joints", view, by="set", width=2.0)
    cracks = show_lines(folder, "cracks", view, by="mode")
    cracks.SetRepresentationType("Points")
    cracks.PointSize = 6
    pv.GetAnimationScene().UpdateAnimationUsingDataTimeSteps()
    times = pv.GetTimeKeeper().TimestepValues  # a single snapshot's time comes as a number
    pv.GetAnimationScene().AnimationTime = times if isinstance(times, (int, float)) else list(times)[-1]
    view.InteractionMode = "2D"
    view.ResetCamera()
    pv.SaveScreenshot(png, view, ImageResolution=[WIDTH, HEIGHT])


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])

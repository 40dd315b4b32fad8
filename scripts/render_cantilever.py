"""Render the showcase (prm/cantilever.prm) for doc/tutorials/step-1-laminate:
the deformed plate (displacement x 2) coloured by the Hoffman index, plies
shown by the mesh. Run with ParaView's pvpython under a virtual display:
    xvfb-run -a pvpython scripts/render_cantilever.py output-cantilever/solution.pvd out.png
"""
import sys
from paraview.simple import (OpenDataFile, WarpByVector, Show, GetActiveViewOrCreate,
                             ColorBy, GetColorTransferFunction, GetScalarBar,
                             GetActiveCamera, SaveScreenshot, Render)

reader = OpenDataFile(sys.argv[1])
warp = WarpByVector(Input=reader)
warp.Vectors = ["POINTS", "displacement"]
warp.ScaleFactor = 2.0
view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [1200, 520]
view.Background = [1, 1, 1]
try:
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass
display = Show(warp, view)
display.Representation = "Surface"
ColorBy(display, ("POINTS", "hoffman_index"))
lut = GetColorTransferFunction("hoffman_index")
lut.ApplyPreset("Cool to Warm", True)
display.SetScalarBarVisibility(view, True)
bar = GetScalarBar(lut, view)
bar.Title = "Hoffman index"
bar.ComponentTitle = ""
bar.TitleColor = [0, 0, 0]
bar.LabelColor = [0, 0, 0]
view.OrientationAxesVisibility = 0
view.CameraPosition = [-20, -70, 40]
view.CameraFocalPoint = [50, 10, -2]
view.CameraViewUp = [0, 0, 1]
view.ResetCamera()
GetActiveCamera().Dolly(2.6)
view.CameraFocalPoint = [50, 10, -2]
Render(view)
SaveScreenshot(sys.argv[2], view, ImageResolution=[1200, 520])

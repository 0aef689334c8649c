# Draws docs/examples/plaque_trou/plaque_trou_sixx.png from the study's VTK output:
#   xvfb-run -a pvbatch render.py plaque_trou/plaque_trou.pvd plaque_trou_sixx.png
# (ParaView 5.11, Debian's paraview package.)
import sys
from paraview.simple import *

result = PVDReader(FileName=sys.argv[1])
view = CreateView('RenderView')
view.ViewSize = [1100, 760]
view.OrientationAxesVisibility = 0
view.Background = [1, 1, 1]
try:
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass
shown = Show(result, view)
shown.SetRepresentationType('Surface With Edges')
shown.EdgeColor = [0.25, 0.25, 0.25]
ColorBy(shown, ('POINTS', 'SIGM_NOEU', 'SIXX'))
lut = GetColorTransferFunction('SIGM_NOEU')
lut.VectorMode = 'Component'
lut.VectorComponent = 0
lut.ApplyPreset('Jet', True)
lut.RescaleTransferFunction(-40.0, 310.0)
bar = GetScalarBar(lut, view)
bar.Title = 'SIGM_NOEU SIXX (MPa)'
bar.ComponentTitle = ''
bar.TitleColor = [0, 0, 0]
bar.LabelColor = [0, 0, 0]
bar.WindowLocation = 'Any Location'
bar.Position = [0.89, 0.1]
bar.ScalarBarLength = 0.8
shown.SetScalarBarVisibility(view, True)
# The hole's neighbourhood: x in [0, 50], y in [0, 42] mm.
view.CameraPosition = [29, 20.5, 200]
view.CameraFocalPoint = [29, 20.5, 0]
view.CameraViewUp = [0, 1, 0]
view.CameraParallelProjection = 1
view.CameraParallelScale = 21.5
SaveScreenshot(sys.argv[2], view, ImageResolution=[1100, 760])

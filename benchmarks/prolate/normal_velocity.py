# SPDX-License-Identifier: LGPL-2.1-or-later
"""Render u·ν (velocity dot the output's normal field) with the mesh edges at the last time of a run.

    xvfb-run -a -s "-screen 0 1280x1024x24" pvpython benchmarks/prolate/normal_velocity.py RESULTS/solution.pvd out.png

Used for the figure of the mesh-imprinted normal velocity in benchmarks/prolate/README.md.
"""
import sys

from paraview.simple import Calculator, ColorBy, GetActiveViewOrCreate, PVDReader, SaveScreenshot, Show

reader = PVDReader(FileName=sys.argv[1])
reader.UpdatePipelineInformation()
normal_velocity = Calculator(Input=reader)
normal_velocity.ResultArrayName = "u_n"
normal_velocity.Function = "dot(velocity,normal)"
view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [900, 900]
view.ViewTime = reader.TimestepValues[-1]
display = Show(normal_velocity, view)
display.SetRepresentationType("Surface With Edges")
ColorBy(display, ("POINTS", "u_n"))
display.RescaleTransferFunctionToDataRange(False, True)
display.SetScalarBarVisibility(view, True)
view.CameraPosition = [4, -4, 1]
view.CameraFocalPoint = [0, 0, 0]
view.CameraViewUp = [0, 0, 1]
view.ResetCamera()
SaveScreenshot(sys.argv[2], view)
print("t =", reader.TimestepValues[-1])

# view.py: opens an isopound animation ready to watch. Written by `isopound-post animate`.
#   paraview --script=view.py            the animation in the ParaView GUI (press Play)
#   pvpython view.py --png DIR           every frame as DIR/frame.NNNN.png, headless under Xvfb
#   pvpython view.py --video FILE.avi    the animation as a video (.avi, or .ogv)
#   pvpython view.py --time T --screenshot FILE.png     one frame
# Frames are dense inside contact episodes: played one frame per tick, the animation slows down at
# every impact; the on-screen slow-motion factor says by how much.
import argparse
import json
import os
import sys

from paraview.simple import *  # noqa: F401,F403

PVD = "@PVD@"
ABSOLUTE_DIR = "@ABSOLUTE_DIR@"
THREE_D = @THREE_D@
# Displacements drawn x SCALE, gaps too (so that bodies touch exactly when in contact). Chosen by
# `isopound-post animate` so that the largest displacement is drawn 4 to 10 % of the site's size
# (--view-scale sets it); change it here.
SCALE = @SCALE@
FRAME_SCALE = @FRAME_SCALE@  # displacements drawn x FRAME_SCALE in the frames (animate --scale)
FRAME_GAP_SCALE = @FRAME_GAP_SCALE@  # gaps drawn x this in the frames
FPS = @FPS@  # regular frames per second of analysis time
EXAGGERATION = @EXAGGERATION@  # contact overlap depth drawn x EXAGGERATION
PEAK_NORMAL_FORCE = @PEAK_NORMAL_FORCE@  # N, the run's largest contact force
PEAK_PENETRATION = @PEAK_PENETRATION@  # m
FORCE_LENGTH = @FORCE_LENGTH@  # m, drawn length of the peak force arrow
FORCE_UNIT = "@FORCE_UNIT@"  # contact forces shown in MN where the peak reaches 1 MN, else kN
NEWTONS_PER_UNIT = @NEWTONS_PER_UNIT@

BLOCKS = ["slab", "column", "bearing", "wall"]
BLOCK_RGB = [[0.12, 0.47, 0.71], [0.25, 0.25, 0.25], [0.17, 0.63, 0.17], [0.72, 0.72, 0.70]]  # wall: concrete
ARROW_RGB = [0.9, 0.0, 0.78]
RUBBER_RGB = [0.95, 0.55, 0.05]


def animation_file():
    try:
        here = os.path.dirname(os.path.abspath(__file__))
    except NameError:  # some GUI script runners define no __file__
        here = os.getcwd()
    for folder in (here, os.getcwd(), ABSOLUTE_DIR):
        if os.path.isfile(os.path.join(folder, PVD)):
            return os.path.join(folder, PVD)
    sys.exit("view.py: cannot find %s beside the script, in the working directory or in %s"
             % (PVD, ABSOLUTE_DIR))


def threshold(source, name, low, high):
    t = Threshold(registrationName=name, Input=source)
    t.Scalars = ["CELLS", "block"]
    t.LowerThreshold = low
    t.UpperThreshold = high
    t.ThresholdMethod = "Between"
    return t


def build(view):
    reader = PVDReader(registrationName="isopound animation", FileName=animation_file())
    # One frame per time step of the .pvd. (Not UpdateAnimationUsingDataTimeSteps(): in the
    # ParaView 5.11 GUI it blocks a --script; the time keeper has the reader's steps anyway.)
    scene = GetAnimationScene()
    scene.PlayMode = "Snap To TimeSteps"

    # Displacements x SCALE: the frames' points move by (SCALE - FRAME_SCALE) x their true
    # displacement, and walls and neighbours by their gap at rest, so that gaps are drawn x SCALE.
    moved = WarpByVector(registrationName="displacements x %g" % SCALE, Input=reader)
    moved.Vectors = ["POINTS", "displacement"]
    moved.ScaleFactor = SCALE - FRAME_SCALE
    gaps = WarpByVector(registrationName="gaps x %g" % SCALE, Input=moved)
    gaps.Vectors = ["POINTS", "gap_offset"]
    gaps.ScaleFactor = SCALE - FRAME_GAP_SCALE

    # The overlap of two bodies is under a millimetre deep: stretch it along the contact normal.
    warp = WarpByVector(registrationName="overlap depth x %g" % EXAGGERATION, Input=gaps)
    warp.Vectors = ["POINTS", "contact_depth_offset"]
    warp.ScaleFactor = EXAGGERATION - 1.0

    # A 3D building see-through, so that contacts under its floors stay in sight; walls opaque.
    body = threshold(warp, "building", 0, 2)
    body_display = Show(body, view)
    ColorBy(body_display, ("CELLS", "block"))
    body_display.Opacity = 0.45 if THREE_D else 1.0
    walls = threshold(warp, "walls", 3, 3)
    walls_display = Show(walls, view)
    ColorBy(walls_display, ("CELLS", "block"))
    block_lut = GetColorTransferFunction("block")
    block_lut.InterpretValuesAsCategories = 1
    block_lut.Annotations = sum([[str(i), n] for i, n in enumerate(BLOCKS)], [])
    block_lut.IndexedColors = sum(BLOCK_RGB, [])
    body_display.SetScalarBarVisibility(view, False)
    walls_display.SetScalarBarVisibility(view, False)

    # Rubber bumpers (3D): the strips glued to walls and slab faces, in the rubber's colour.
    rubber = threshold(warp, "rubber", 7, 7)
    rubber_display = Show(rubber, view)
    rubber_display.ColorArrayName = ['CELLS', '']
    rubber_display.AmbientColor = RUBBER_RGB
    rubber_display.DiffuseColor = RUBBER_RGB

    contact = threshold(warp, "contacts", 4, 4)
    contact_force = Calculator(registrationName="normal force in " + FORCE_UNIT, Input=contact)
    contact_force.AttributeType = "Cell Data"
    contact_force.ResultArrayName = "F_N [%s]" % FORCE_UNIT
    contact_force.Function = "normal_force/%g" % NEWTONS_PER_UNIT
    contact_display = Show(contact_force, view)
    # Outlined thick: an overlap a few millimetres deep still shows at building scale.
    contact_display.Representation = "Surface With Edges"
    contact_display.EdgeColor = [0.8, 0.0, 0.0]
    contact_display.LineWidth = 4.0
    # Coloured without ColorBy, which rescales to the (often empty) first frame and warns.
    force_lut = GetColorTransferFunction("F_N [%s]" % FORCE_UNIT)
    contact_display.ColorArrayName = ["CELLS", "F_N [%s]" % FORCE_UNIT]
    contact_display.LookupTable = force_lut
    force_lut.AutomaticRescaleRangeMode = "Never"
    top = max(PEAK_NORMAL_FORCE / NEWTONS_PER_UNIT, 1e-3)
    # Warm colours only (yellow at zero to dark red at the peak): a contact never looks like a
    # slab or a wall, whatever its force.
    force_lut.RGBPoints = [0.0, 1.0, 0.85, 0.0, 0.5 * top, 1.0, 0.35, 0.0, top, 0.8, 0.0, 0.0]
    force_lut.RescaleTransferFunction(0.0, top)
    bar = GetScalarBar(force_lut, view)
    bar.Title = "contact F_N [%s]" % FORCE_UNIT
    bar.ComponentTitle = ""
    bar.RangeLabelFormat = "%-.3g"
    contact_display.SetScalarBarVisibility(view, True)

    # Forces on the building as arrows; 3D frames carry the force on B (the wall or neighbour).
    centres = CellCenters(registrationName="contact centres", Input=contact)
    force_on_building = Calculator(registrationName="force on the building", Input=centres)
    force_on_building.ResultArrayName = "force_on_building"
    force_on_building.Function = "-contact_force" if THREE_D else "contact_force"
    arrows = Glyph(registrationName="contact force arrows", Input=force_on_building,
                   GlyphType="Arrow")
    arrows.OrientationArray = ["POINTS", "force_on_building"]
    arrows.ScaleArray = ["POINTS", "force_on_building"]
    arrows.ScaleFactor = FORCE_LENGTH / max(PEAK_NORMAL_FORCE, 1.0)
    arrows.GlyphMode = "All Points"
    arrows_display = Show(arrows, view)
    arrows_display.ColorArrayName = ['POINTS', '']
    arrows_display.AmbientColor = ARROW_RGB
    arrows_display.DiffuseColor = ARROW_RGB

    clock = PythonAnnotation(registrationName="time", Input=reader)
    clock.ArrayAssociation = "Field Data"
    clock.Expression = "'t = %.4f s   slow motion x%.0f' % (t_value, slow_motion[0])"
    clock_display = Show(clock, view)
    clock_display.WindowLocation = "Upper Center"
    clock_display.FontSize = 18

    note = Text(registrationName="scales")
    note.Text = ("displacements and gaps drawn x %g   contact overlap depth x %g   arrows: contact "
                 "force on the building, peak %.3g %s = %g m"
                 % (SCALE, EXAGGERATION, PEAK_NORMAL_FORCE / NEWTONS_PER_UNIT, FORCE_UNIT,
                    FORCE_LENGTH))
    note_display = Show(note, view)
    note_display.WindowLocation = "Lower Left Corner"
    note_display.FontSize = 14
    return {"reader": reader, "contact": contact, "centres": centres, "moved": moved,
            "gaps": gaps, "bar": bar, "lut": force_lut, "note": note}


def place_camera(view, reader, drawn):
    drawn.UpdatePipeline(reader.TimestepValues[0] if reader.TimestepValues else 0.0)
    x0, x1, y0, y1, z0, z1 = drawn.GetDataInformation().GetBounds()
    centre = [0.5 * (x0 + x1), 0.5 * (y0 + y1), 0.5 * (z0 + z1)]
    if THREE_D:  # from the south-west, 30 degrees above (the preview's view)
        direction = [-0.4967, -0.7094, 0.5]
    else:  # from the front (-y), upright
        direction = [0.0, -1.0, 0.0]
    distance = 3.0 * max(x1 - x0, y1 - y0, z1 - z0, 1.0)
    view.CameraFocalPoint = centre
    view.CameraPosition = [c + distance * d for c, d in zip(centre, direction)]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.ResetCamera(False)


def contact_report(view, contact, centres, t, size):
    contact.UpdatePipeline(t)
    cells = contact.GetDataInformation().GetNumberOfCells()
    out = {"time": view.ViewTime, "contact_cells": cells}
    if cells:
        data = servermanager.Fetch(centres)
        points = [data.GetPoint(i) for i in range(data.GetNumberOfPoints())]
        centroid = [sum(p[k] for p in points) / len(points) for k in range(3)]
        renderer = view.GetRenderer()
        renderer.SetWorldPoint(centroid[0], centroid[1], centroid[2], 1.0)
        renderer.WorldToDisplay()
        x, y, _ = renderer.GetDisplayPoint()
        out["centroid"] = centroid
        out["pixel"] = [x, size[1] - 1 - y]  # PNG row 0 at the top
    return out


def main():
    parser = argparse.ArgumentParser(description="Open an isopound animation ready to watch.")
    parser.add_argument("--png", help="write every frame as DIR/frame.NNNN.png")
    parser.add_argument("--video", help="write the animation as a video (.avi or .ogv)")
    parser.add_argument("--time", type=float, action="append", default=[],
                        help="a frame time in s (with --screenshot or --report)")
    parser.add_argument("--screenshot", help="write the frame at --time as a PNG")
    parser.add_argument("--report", help="write time steps and contact cells as JSON")
    parser.add_argument("--size", type=int, nargs=2, default=[1280, 720])
    args, _ = parser.parse_known_args(sys.argv[1:])

    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = args.size
    view.OrientationAxesVisibility = 1
    parts = build(view)
    reader, contact, centres = parts["reader"], parts["contact"], parts["centres"]
    place_camera(view, reader, parts["gaps"])
    scene = GetAnimationScene()
    times = list(reader.TimestepValues)
    bar_range = parts["lut"].RGBPoints
    report = {"time_steps": times, "frames": [],
              "scale": SCALE,
              "displacement_warp": parts["moved"].ScaleFactor,
              "gap_warp": parts["gaps"].ScaleFactor,
              "colour_bar": {"title": parts["bar"].Title,
                             "range": [bar_range[0], bar_range[-4]]},
              "note": parts["note"].Text}
    for t in args.time:
        scene.AnimationTime = t
        view.ViewTime = t
        Render(view)
        if args.screenshot:
            SaveScreenshot(args.screenshot, view, ImageResolution=args.size)
        report["frames"].append(contact_report(view, contact, centres, t, args.size))
    if args.png:
        os.makedirs(args.png, exist_ok=True)
        SaveAnimation(os.path.join(args.png, "frame.png"), view, ImageResolution=args.size)
    if args.video:
        SaveAnimation(args.video, view, ImageResolution=args.size, FrameRate=int(round(FPS)))
    if args.report:
        with open(args.report, "w") as f:
            json.dump(report, f)
    if not (args.png or args.video or args.screenshot or args.report):
        Render(view)


main()

#!/usr/bin/env python3
"""Opens a plyimpact result folder with the damage of every ply side by side, seen from above, and,
when the folder has them, the interfaces' damage (interfaces.pvd) and the projected delamination
map (cscan.vtu).

  In ParaView:  pvpython tools/paraview_view.py RESULT_DIR   (or Tools > Python Shell > Run Script,
                after setting sys.argv = ["paraview_view.py", "RESULT_DIR"]), then scrub the time.
  Without ParaView (VTK's Python, e.g. Debian's python3-vtk9; needs X, or xvfb-run -a):
                python3 tools/paraview_view.py RESULT_DIR [--time T] [--png FILE]

Both front ends run the same pipeline (paraview_view_pipeline.py, plain VTK): ParaView calls it
from Programmable Filters, so the view follows the time; the VTK front end reads the .pvd itself
(plain VTK has no PVD reader) and renders one time, on screen or to a PNG.
"""

import argparse
import glob
import os
import sys
import xml.etree.ElementTree as ET

TOOLS = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, TOOLS)
import paraview_view_pipeline as pipeline  # noqa: E402


# ---------------------------------------------------------------------------- result folder
def find_result(folder):
    """Paths of a result folder: the frames' .pvd (the one that is not interfaces.pvd), and
    interfaces.pvd and cscan.vtu when present (None otherwise)."""
    pvds = sorted(p for p in glob.glob(os.path.join(folder, "*.pvd")) if os.path.basename(p) != "interfaces.pvd")
    if not pvds:
        raise SystemExit("paraview_view: no frames (*.pvd) in %s" % folder)
    interfaces = os.path.join(folder, "interfaces.pvd")
    cscan = os.path.join(folder, "cscan.vtu")
    return {"frames": pvds[0], "interfaces": interfaces if os.path.exists(interfaces) else None,
            "cscan": cscan if os.path.exists(cscan) else None}


def read_pvd(path):
    """[(time, [(part, name, file), ...]), ...] sorted by time, files as absolute paths."""
    root = ET.parse(path).getroot()
    times = {}
    for ds in root.iter("DataSet"):
        t = float(ds.get("timestep", "0"))
        f = os.path.join(os.path.dirname(os.path.abspath(path)), ds.get("file"))
        times.setdefault(t, []).append((int(ds.get("part", "0")), ds.get("name"), f))
    return sorted((t, sorted(parts)) for t, parts in times.items())


# ---------------------------------------------------------------------------- VTK front end
def _read_vtk_xml(path):
    """A .vtu, or a .vtm multiblock (the interfaces' frames)."""
    from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataReader, vtkXMLUnstructuredGridReader
    r = vtkXMLMultiBlockDataReader() if path.endswith(".vtm") else vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    return r.GetOutputDataObject(0)


def read_frame(pvd, time=None):
    """The frame at the series' time nearest `time` (the last when None), structured as ParaView's
    PVD reader delivers it: the data set itself for one part, else a multiblock of named blocks,
    each a multiblock of its piece. Returns (time, data)."""
    from vtkmodules.vtkCommonDataModel import vtkCompositeDataSet, vtkMultiBlockDataSet
    series = read_pvd(pvd)
    if not series:
        raise SystemExit("paraview_view: %s lists no data sets" % pvd)
    t, parts = series[-1] if time is None else min(series, key=lambda e: abs(e[0] - time))
    if len(parts) == 1:
        return t, _read_vtk_xml(parts[0][2])
    mb = vtkMultiBlockDataSet()
    mb.SetNumberOfBlocks(len(parts))
    for i, (_, name, f) in enumerate(parts):
        piece = vtkMultiBlockDataSet()
        piece.SetNumberOfBlocks(1)
        piece.SetBlock(0, _read_vtk_xml(f))
        mb.SetBlock(i, piece)
        if name:
            mb.GetMetaData(i).Set(vtkCompositeDataSet.NAME(), name)
    return t, mb


def _categorical_lut():
    from vtkmodules.vtkCommonCore import vtkLookupTable, vtkVariant
    lut = vtkLookupTable()
    lut.SetIndexedLookup(1)
    lut.SetNumberOfTableValues(len(pipeline.DAMAGE_CATEGORIES))
    for i, (value, rgb, label) in enumerate(pipeline.DAMAGE_CATEGORIES):
        lut.SetTableValue(i, rgb[0], rgb[1], rgb[2], 1.0)
        lut.SetAnnotation(vtkVariant(float(value)), label)
    lut.SetNanColor(0.6, 0.6, 0.95, 1.0)
    return lut


def render_vtk(result, time=None, png=None):
    """Builds the view with plain VTK; writes `png` (off screen) or opens a window."""
    from vtkmodules.vtkCommonCore import vtkLookupTable
    from vtkmodules.vtkIOImage import vtkPNGWriter
    from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor
    from vtkmodules.vtkRenderingCore import (vtkActor, vtkDataSetMapper, vtkRenderer, vtkRenderWindow,
                                             vtkRenderWindowInteractor, vtkTextActor, vtkWindowToImageFilter)
    import vtkmodules.vtkInteractionStyle  # noqa: F401  (default interactor style)
    import vtkmodules.vtkRenderingFreeType  # noqa: F401  (text)
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (render window implementation)

    t, frame = read_frame(result["frames"], time)
    renderer = vtkRenderer()
    renderer.SetBackground(*pipeline.BACKGROUND)
    bounds = pipeline.plate_bounds(frame)

    def add(data, lut=None, array=None, assoc="CELLS", colour=None):
        if data is None or data.GetNumberOfCells() == 0:
            return None
        mapper = vtkDataSetMapper()
        mapper.SetInputData(data)
        if array is not None:
            mapper.SetScalarModeToUseCellFieldData() if assoc == "CELLS" else mapper.SetScalarModeToUsePointFieldData()
            mapper.SelectColorArray(array)
            mapper.SetLookupTable(lut)
            mapper.SetUseLookupTableScalarRange(1)
            mapper.ScalarVisibilityOn()
        else:
            mapper.ScalarVisibilityOff()
        actor = vtkActor()
        actor.SetMapper(mapper)
        if colour is not None:
            actor.GetProperty().SetColor(*colour)
        renderer.AddActor(actor)
        return actor

    lut = _categorical_lut()
    add(pipeline.ply_tiles(frame), lut, pipeline.DAMAGE_ARRAY)
    interfaces = read_frame(result["interfaces"], t)[1] if result["interfaces"] else None
    cscan = _read_vtk_xml(result["cscan"]) if result["cscan"] else None
    add(pipeline.tile_labels(frame, interfaces, cscan), colour=pipeline.LABEL_COLOUR)
    if interfaces is not None:
        ilut = vtkLookupTable()
        ilut.SetRange(*pipeline.INTERFACE_RANGE)
        ilut.SetHueRange(0.66, 0.0)
        ilut.Build()
        add(pipeline.interface_tiles(interfaces, bounds), ilut, pipeline.INTERFACE_ARRAY[1], pipeline.INTERFACE_ARRAY[0])
    if cscan is not None:
        tile = pipeline.cscan_tile(cscan, bounds)
        chosen = pipeline.colour_array(tile) if tile.GetNumberOfCells() else None
        clut = vtkLookupTable()
        if chosen:
            attr = tile.GetCellData() if chosen[0] == "CELLS" else tile.GetPointData()
            clut.SetRange(attr.GetArray(chosen[1]).GetRange(0))
        clut.SetNanColor(*pipeline.NAN_COLOUR, 1.0)
        clut.Build()
        add(tile, clut, chosen[1] if chosen else None, chosen[0] if chosen else "CELLS")

    bar = vtkScalarBarActor()
    bar.SetLookupTable(lut)
    bar.SetTitle("failed modes")
    bar.SetNumberOfLabels(len(pipeline.DAMAGE_CATEGORIES))
    bar.GetTitleTextProperty().SetColor(*pipeline.LABEL_COLOUR)
    bar.GetLabelTextProperty().SetColor(*pipeline.LABEL_COLOUR)
    bar.SetPosition(0.90, 0.1)
    bar.SetWidth(0.08)
    renderer.AddActor2D(bar)
    title = vtkTextActor()
    title.SetInput("%s   t = %.4g s" % (os.path.basename(result["frames"]), t))
    title.GetTextProperty().SetColor(*pipeline.LABEL_COLOUR)
    title.GetTextProperty().SetFontSize(20)
    title.SetPosition(10, 10)
    renderer.AddActor2D(title)

    camera = renderer.GetActiveCamera()
    camera.ParallelProjectionOn()
    camera.SetPosition(0, 0, 1)
    camera.SetFocalPoint(0, 0, 0)
    camera.SetViewUp(0, 1, 0)
    renderer.ResetCamera()

    window = vtkRenderWindow()
    window.AddRenderer(renderer)
    window.SetSize(*pipeline.WINDOW_SIZE)
    if png:
        window.SetOffScreenRendering(1)
        window.Render()
        grab = vtkWindowToImageFilter()
        grab.SetInput(window)
        grab.ReadFrontBufferOff()
        grab.Update()
        writer = vtkPNGWriter()
        writer.SetFileName(png)
        writer.SetInputConnection(grab.GetOutputPort())
        writer.Write()
        return t
    interactor = vtkRenderWindowInteractor()
    interactor.SetRenderWindow(window)
    window.Render()
    interactor.Start()
    return t


# ---------------------------------------------------------------------------- ParaView front end
def _programmable(simple, source, function, output_type, name, extra_args=""):
    """A Programmable Filter that runs pipeline.<function>(input) on its input at every time."""
    script = ("import sys\nsys.path.insert(0, %r)\nimport paraview_view_pipeline as pipeline\n"
              "self.GetOutputDataObject(0).ShallowCopy(pipeline.%s(self.GetInputDataObject(0, 0)%s))\n"
              % (TOOLS, function, extra_args))
    f = simple.ProgrammableFilter(registrationName=name, Input=source)
    f.OutputDataSetType = output_type
    f.Script = script
    return f


def render_paraview(simple, result, time=None, png=None):
    view = simple.GetActiveViewOrCreate("RenderView")
    view.Background = list(pipeline.BACKGROUND)
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    frames = simple.PVDReader(registrationName=os.path.basename(result["frames"]), FileName=result["frames"])
    simple.Hide(frames, view)  # the full 3-D scene (plies and impactor): click its eye to see it
    scene = simple.GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    times = list(frames.TimestepValues) if frames.TimestepValues else [0.0]
    scene.AnimationTime = times[-1] if time is None else min(times, key=lambda v: abs(v - time))

    plies = _programmable(simple, frames, "ply_tiles", "vtkUnstructuredGrid", "ply damage")
    display = simple.Show(plies, view)
    simple.ColorBy(display, ("CELLS", pipeline.DAMAGE_ARRAY))
    lut = simple.GetColorTransferFunction(pipeline.DAMAGE_ARRAY)
    lut.InterpretValuesAsCategories = 1
    lut.Annotations = [x for v, _, label in pipeline.DAMAGE_CATEGORIES for x in (str(v), label)]
    lut.IndexedColors = [c for _, rgb, _ in pipeline.DAMAGE_CATEGORIES for c in rgb]
    display.SetScalarBarVisibility(view, True)
    bounds = "pipeline.plate_bounds(self.GetInputDataObject(0, 1))"
    label_inputs = [frames]
    if result["interfaces"]:
        interfaces = simple.PVDReader(registrationName="interfaces.pvd", FileName=result["interfaces"])
        simple.Hide(interfaces, view)
        tiles = simple.ProgrammableFilter(registrationName="interface damage", Input=[interfaces, frames])
        tiles.OutputDataSetType = "vtkUnstructuredGrid"
        tiles.Script = ("import sys\nsys.path.insert(0, %r)\nimport paraview_view_pipeline as pipeline\n"
                        "self.GetOutputDataObject(0).ShallowCopy(pipeline.interface_tiles("
                        "self.GetInputDataObject(0, 0), %s))\n" % (TOOLS, bounds))
        simple.ColorBy(simple.Show(tiles, view), pipeline.INTERFACE_ARRAY)
        simple.GetColorTransferFunction(pipeline.INTERFACE_ARRAY[1]).RescaleTransferFunction(*pipeline.INTERFACE_RANGE)
        label_inputs.append(interfaces)
    if result["cscan"]:
        cscan = simple.XMLUnstructuredGridReader(registrationName="cscan.vtu", FileName=[result["cscan"]])
        simple.Hide(cscan, view)
        tile = simple.ProgrammableFilter(registrationName="C-scan", Input=[cscan, frames])
        tile.OutputDataSetType = "vtkUnstructuredGrid"
        tile.Script = ("import sys\nsys.path.insert(0, %r)\nimport paraview_view_pipeline as pipeline\n"
                       "self.GetOutputDataObject(0).ShallowCopy(pipeline.cscan_tile("
                       "self.GetInputDataObject(0, 0), %s))\n" % (TOOLS, bounds))
        shown = simple.Show(tile, view)
        simple.UpdatePipeline(proxy=tile)
        chosen = pipeline.colour_array(simple.servermanager.Fetch(tile))
        if chosen:
            simple.ColorBy(shown, chosen)
            simple.GetColorTransferFunction(chosen[1]).NanColor = list(pipeline.NAN_COLOUR)
        label_inputs.append(cscan)

    # Labels of every tile; inputs: frames, then interfaces and cscan when present.
    labels = simple.ProgrammableFilter(registrationName="labels", Input=label_inputs)
    labels.OutputDataSetType = "vtkPolyData"
    arg = {"interfaces": "None", "cscan": "None"}
    k = 1
    for key in ("interfaces", "cscan"):
        if result[key]:
            arg[key] = "self.GetInputDataObject(0, %d)" % k
            k += 1
    labels.Script = ("import sys\nsys.path.insert(0, %r)\nimport paraview_view_pipeline as pipeline\n"
                     "self.GetOutputDataObject(0).ShallowCopy(pipeline.tile_labels(self.GetInputDataObject(0, 0), "
                     "%s, %s))\n" % (TOOLS, arg["interfaces"], arg["cscan"]))
    shown = simple.Show(labels, view)
    simple.ColorBy(shown, None)
    shown.AmbientColor = list(pipeline.LABEL_COLOUR)
    shown.DiffuseColor = list(pipeline.LABEL_COLOUR)

    view.CameraParallelProjection = 1
    view.CameraPosition = [0, 0, 1]
    view.CameraFocalPoint = [0, 0, 0]
    view.CameraViewUp = [0, 1, 0]
    view.ResetCamera()
    view.ViewSize = list(pipeline.WINDOW_SIZE)
    simple.Render(view)
    if png:
        simple.SaveScreenshot(png, view, ImageResolution=list(pipeline.WINDOW_SIZE))
    return scene.AnimationTime


# ---------------------------------------------------------------------------- main
def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("result", help="result folder of plyimpact run (holds <scene>.pvd)")
    parser.add_argument("--time", type=float, help="time to show, s (default: the last frame)")
    parser.add_argument("--png", help="write the view to this PNG instead of showing it")
    parser.add_argument("--vtk", action="store_true", help="use plain VTK even where ParaView is available")
    args = parser.parse_args(argv)
    result = find_result(args.result)
    simple = None
    if not args.vtk:
        try:
            from paraview import simple
        except ImportError:
            simple = None
    if simple is not None:
        t = render_paraview(simple, result, args.time, args.png)
    else:
        t = render_vtk(result, args.time, args.png)
    if args.png:
        print("paraview_view: %s at t = %.6g s -> %s" % (result["frames"], t, args.png))


if __name__ == "__main__":
    main()

"""tools/paraview_view.py rendered headlessly with VTK's Python (the path taken without ParaView), on
a real run and on the same run with an interface series and a C-scan added, so that the script
cannot break silently. Run by ctest under xvfb-run (Debian's VTK needs an X server even off
screen).

The run: a small [45/0/-45/90] *MAT_054 plate struck at 100 m/s by a rigid sphere, which fails
and erodes elements within 20 us. The checks compare the image with the frame it shows, read
independently with VTK's XML reader:
  - every damage category (0-4 failed modes, eroded) that some ply cell has appears in the tiles'
    part of the image, and none that no cell has: a wrong array, colour map or tile would show. A
    pixel matches a category when each channel is within 0.04 of its colour (the view looks
    straight down the headlight: flat faces get their full colour; 8-bit rounding is 0.002, and
    the categories differ by 0.1 or more in some channel);
  - the tiles are where the layout puts them: columns of the image holding at least 30 drawn
    pixels (a tile is about 110 pixels tall, a label line 12) form one run per tile: 4 for the
    plies; with interfaces.pvd (two interfaces, damage 0 ... 1 across each) and cscan.vtu added,
    7: the C-scan left of the plies (its delaminated patch), the two interfaces right of them, drawn
    with the blue-to-red damage ramp.
  - the ParaView front end, driven through a stand-in for paraview.simple that records the
    Programmable Filters it creates (ParaView itself cannot be installed beside python3-vtk9 on
    Debian 12): each filter's script, run on the same inputs, gives the same number of cells as
    the pipeline function the VTK front end calls. This catches a broken script string or call.
The interface and C-scan files are written here in the documented layout (docs/outputs.md):
interfaces.pvd -> one .vtm per time with one named block per interface, point data `damage`;
cscan.vtu with cell data `depth_shallowest` (NaN where nothing is delaminated).
"""

import argparse
import os
import shutil
import subprocess
import sys

SCENE = """units: mm-t-s-MPa
control: {termination_time: 2.0e-5}
output: {interval: 1.0e-5}
materials:
  ply: {card: MAT_054, RO: 1.55e-9, EA: 157 GPa, EB: 8.5 GPa, EC: 8.5 GPa, PRBA: 0.01895, PRCA: 0.01895, PRCB: 0.53,
        GAB: 4.2 GPa, GBC: 2.2 GPa, GCA: 4.2 GPa, AOPT: 2, A: [1, 0, 0], D: [0, 1, 0],
        XT: 2.2 GPa, XC: 1.2 GPa, YT: 0.045 GPa, YC: 0.28 GPa, SC: 0.045 GPa,
        DFAILM: 0.02, DFAILT: 0.02, DFAILC: -0.02, DFAILS: 0.03}
  steel: {card: MAT_001, RO: 7.857e-9, E: 206.7 GPa, PR: 0.3}
sections:
  ply: {ELFORM: 1, IHQ: 2, QM: 0.1}
laminate:
  length: 20
  width: 20
  ply_thickness: 0.25
  stacking: "[45/0/-45/90]"
  material: ply
  section: ply
  element_size: 1
  interfaces: angle-change
  supports:
    window: {window: [16, 16]}
impactor: {shape: sphere, diameter: 6, mass: 0.01 kg, gap: 0.05, velocity: 100 m/s, element_size: 1, rigid: true,
           material: steel}
contacts:
  - {name: impact, type: eroding_surface_to_surface, surfaces: [impactor, [ply_1_45, ply_2_0, ply_3_m45, ply_4_90]],
     SOFT: 1}
"""

TOLERANCE = 0.04
failures = []


def check(condition, message):
    print(("ok    " if condition else "FAIL  ") + message)
    if not condition:
        failures.append(message)


def read_png(path):
    from vtkmodules.vtkIOImage import vtkPNGReader
    r = vtkPNGReader()
    r.SetFileName(path)
    r.Update()
    img = r.GetOutput()
    nx, ny, _ = img.GetDimensions()
    a = img.GetPointData().GetScalars()
    nc = a.GetNumberOfComponents()
    raw = bytes(memoryview(a))  # row by row from the bottom, nc bytes per pixel
    scale = 1.0 / 255.0
    pixels = [(r * scale, g * scale, b * scale) for r, g, b in zip(raw[0::nc], raw[1::nc], raw[2::nc])]
    return nx, ny, nc, pixels


def tile_runs(nx, pixels, background):
    """[(first column, last column), ...] of the runs, at least 10 wide, of columns with at least 30
    drawn pixels, in the tiles' part of the image (left of the scalar bar, above the title line)."""
    counts = [0] * nx
    for k, p in enumerate(pixels):
        x, y = k % nx, k // nx
        if y > 40 and x < 0.88 * nx and not matches(p, background):
            counts[x] += 1
    runs, start = [], None
    for x, c in enumerate(counts + [0]):
        if c >= 30 and start is None:
            start = x
        elif c < 30 and start is not None:
            if x - start >= 10:  # narrower: a stroke of the scalar bar's labels
                runs.append((start, x - 1))
            start = None
    return runs


def matches(p, rgb):
    return all(abs(p[c] - rgb[c]) <= TOLERANCE for c in range(3))


def quad_grid(x0, x1, y0, y1, z, n, point_array=None, cell_array=None):
    """An n x n grid of quads over [x0, x1] x [y0, y1] at height z, with a point array (value per
    point from its x) and/or a cell array (value per cell from its centre)."""
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
    from vtkmodules.vtkCommonDataModel import VTK_QUAD, vtkUnstructuredGrid
    g = vtkUnstructuredGrid()
    pts = vtkPoints()
    for j in range(n + 1):
        for i in range(n + 1):
            pts.InsertNextPoint(x0 + (x1 - x0) * i / n, y0 + (y1 - y0) * j / n, z)
    g.SetPoints(pts)
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            g.InsertNextCell(VTK_QUAD, 4, [a, a + 1, a + n + 2, a + n + 1])
    if point_array:
        arr = vtkDoubleArray()
        arr.SetName(point_array[0])
        for j in range(n + 1):
            for i in range(n + 1):
                arr.InsertNextValue(point_array[1](i / n))
        g.GetPointData().AddArray(arr)
    if cell_array:
        arr = vtkDoubleArray()
        arr.SetName(cell_array[0])
        for j in range(n):
            for i in range(n):
                arr.InsertNextValue(cell_array[1]((i + 0.5) / n, (j + 0.5) / n))
        g.GetCellData().AddArray(arr)
    return g


def add_interfaces_and_cscan(folder, times):
    from vtkmodules.vtkCommonDataModel import vtkCompositeDataSet, vtkMultiBlockDataSet
    from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataWriter, vtkXMLUnstructuredGridWriter
    os.makedirs(os.path.join(folder, "interfaces"), exist_ok=True)
    entries = []
    for k, t in enumerate(times):
        mb = vtkMultiBlockDataSet()
        for b, name in enumerate(["interface_1 (plies 1/2, 45/0)", "interface_2 (plies 2/3, 0/-45)"]):
            mb.SetBlock(b, quad_grid(0, 0.02, 0, 0.02, 0.00025 * (b + 1), 8, point_array=("damage", lambda x: x)))
            mb.GetMetaData(b).Set(vtkCompositeDataSet.NAME(), name)
        w = vtkXMLMultiBlockDataWriter()
        w.SetInputData(mb)
        rel = "interfaces/interfaces_%04d.vtm" % k
        w.SetFileName(os.path.join(folder, rel))
        w.Write()
        entries.append('    <DataSet timestep="%r" group="" part="0" file="%s"/>' % (t, rel))
    with open(os.path.join(folder, "interfaces.pvd"), "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n  <Collection>\n%s\n'
                '  </Collection>\n</VTKFile>\n' % "\n".join(entries))
    nan = float("nan")
    cscan = quad_grid(0, 0.02, 0, 0.02, 0.001, 10,
                      cell_array=("depth_shallowest", lambda x, y: 0.25 if (x - 0.5) ** 2 + (y - 0.5) ** 2 < 0.1 else nan))
    w = vtkXMLUnstructuredGridWriter()
    w.SetInputData(cscan)
    w.SetFileName(os.path.join(folder, "cscan.vtu"))
    w.Write()


def check_paraview_scripts(paraview_view, pipeline, folder):
    import types
    from vtkmodules.vtkCommonDataModel import vtkPolyData, vtkUnstructuredGrid

    class Proxy:
        """Accepts any property and call, as a ParaView proxy would."""
        def __init__(self, **props):
            self.__dict__.update(props)
            self.TimestepValues = []

        def __getattr__(self, name):
            return Proxy()

        def __call__(self, *args, **kwargs):
            return Proxy()

    filters = []

    def programmable_filter(**props):
        f = Proxy(**props)
        filters.append(f)
        return f

    simple = types.SimpleNamespace(ProgrammableFilter=programmable_filter,
                                   servermanager=types.SimpleNamespace(Fetch=lambda proxy: vtkUnstructuredGrid()))
    for name in ("GetActiveViewOrCreate", "PVDReader", "Hide", "GetAnimationScene", "Show", "ColorBy",
                 "GetColorTransferFunction", "XMLUnstructuredGridReader", "UpdatePipeline", "Render"):
        setattr(simple, name, Proxy())
    result = paraview_view.find_result(folder)
    paraview_view.render_paraview(simple, result)
    t, frame = paraview_view.read_frame(result["frames"])
    interfaces = paraview_view.read_frame(result["interfaces"], t)[1]
    cscan = paraview_view._read_vtk_xml(result["cscan"])
    bounds = pipeline.plate_bounds(frame)
    expected = {"ply damage": ([frame], pipeline.ply_tiles(frame)),
                "interface damage": ([interfaces, frame], pipeline.interface_tiles(interfaces, bounds)),
                "C-scan": ([cscan, frame], pipeline.cscan_tile(cscan, bounds)),
                "labels": ([frame, interfaces, cscan], pipeline.tile_labels(frame, interfaces, cscan))}
    check(sorted(f.registrationName for f in filters) == sorted(expected),
          "ParaView front end builds the filters %s" % sorted(f.registrationName for f in filters))
    for f in filters:
        inputs, want = expected[f.registrationName]

        class Filter:
            def GetInputDataObject(self, port, index):
                return inputs[index]

            def GetOutputDataObject(self, port):
                return out

        out = vtkPolyData() if f.OutputDataSetType == "vtkPolyData" else vtkUnstructuredGrid()
        exec(f.Script, {"self": Filter()})
        check(out.GetNumberOfCells() == want.GetNumberOfCells() > 0,
              "ParaView filter '%s' gives %d cells, the VTK pipeline %d" % (f.registrationName, out.GetNumberOfCells(),
                                                                          want.GetNumberOfCells()))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plyimpact", required=True)
    parser.add_argument("--tools", required=True)
    parser.add_argument("--work", required=True)
    args = parser.parse_args()
    sys.path.insert(0, args.tools)
    import paraview_view
    import paraview_view_pipeline as pipeline

    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    scene = os.path.join(args.work, "plate.yaml")
    with open(scene, "w") as f:
        f.write(SCENE)
    out = os.path.join(args.work, "plate")
    subprocess.run([args.plyimpact, "run", scene, "-o", out], check=True, stdout=subprocess.DEVNULL)

    # The plies alone.
    png = os.path.join(args.work, "plies.png")
    subprocess.run([sys.executable, os.path.join(args.tools, "paraview_view.py"), out, "--png", png, "--vtk"], check=True)
    nx, ny, _, pixels = read_png(png)
    check((nx, ny) == pipeline.WINDOW_SIZE, "image size %dx%d" % (nx, ny))
    result = paraview_view.find_result(out)
    t, frame = paraview_view.read_frame(result["frames"])
    tiles = pipeline.ply_tiles(frame)
    values = tiles.GetCellData().GetArray(pipeline.DAMAGE_ARRAY)
    present = {int(values.GetValue(c)) for c in range(tiles.GetNumberOfCells())}
    check(tiles.GetNumberOfCells() == frame.GetBlock(0).GetBlock(0).GetNumberOfCells(),
          "every ply cell is in a tile (%d)" % tiles.GetNumberOfCells())
    check(pipeline.ERODED in present and len(present) >= 3, "the run failed and eroded elements: %s" % sorted(present))
    # The tiles' part of the image: left of the scalar bar, above the title line.
    region = [p for k, p in enumerate(pixels) if (k % nx) < 0.88 * nx and (k // nx) > 40]
    for value, rgb, label in pipeline.DAMAGE_CATEGORIES:
        count = sum(1 for p in region if matches(p, rgb))
        if value in present:
            check(count > 20, "category %s drawn (%d pixels)" % (label, count))
        else:
            check(count == 0, "category %s absent from the data and the image (%d pixels)" % (label, count))
    runs = tile_runs(nx, pixels, pipeline.BACKGROUND)
    check(len(runs) == 4, "four ply tiles side by side: column runs %s" % runs)

    # The same run with interfaces and a C-scan.
    full = os.path.join(args.work, "full")
    shutil.copytree(out, full)
    add_interfaces_and_cscan(full, [e[0] for e in paraview_view.read_pvd(result["frames"])])
    png = os.path.join(args.work, "full.png")
    subprocess.run([sys.executable, os.path.join(args.tools, "paraview_view.py"), full, "--png", png, "--vtk"], check=True)
    nx, ny, _, pixels = read_png(png)
    runs = tile_runs(nx, pixels, pipeline.BACKGROUND)
    check(len(runs) == 7, "C-scan, four plies and two interfaces side by side: column runs %s" % runs)
    if len(runs) == 7:
        def colours(run):
            return [p for k, p in enumerate(pixels) if run[0] <= k % nx <= run[1] and k // nx > 40]
        cscan = colours(runs[0])
        check(sum(1 for p in cscan if not matches(p, pipeline.BACKGROUND)) > 1000, "C-scan patch drawn")
        for run in runs[5:]:
            ramp = colours(run)
            red = sum(1 for p in ramp if p[0] > 0.8 and p[1] < 0.2 and p[2] < 0.2)
            blue = sum(1 for p in ramp if p[2] > 0.8 and p[0] < 0.2 and p[1] < 0.2)
            check(red > 20 and blue > 20, "interface tile %s: damage ramp from blue (0) to red (1), %d blue, %d red "
                  "pixels" % (run, blue, red))

    check_paraview_scripts(paraview_view, pipeline, full)

    if failures:
        print("%d check(s) failed" % len(failures))
        return 1
    print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())

"""The pipeline of tools/paraview_view.py, in plain VTK so that both front ends run the same code:
ParaView calls these functions from Programmable Filters (its Python ships the same vtkmodules),
the VTK-only renderer calls them directly.

The view: every ply of the last frame (or the chosen time) seen from above, side by side in a grid
(ply 1, the bottom ply, first), coloured by how many of its four *MAT_054 failure modes have
failed (0-4) and with eroded elements marked; when the result folder has them, the interfaces
(interfaces.pvd: the damage of each tiebreak interface) in a second grid to the right and the
projected delamination map (cscan.vtu: depth of the shallowest delamination) to the left. Each
tile is labelled ("ply 3  -45", "interface 3 (plies 3/4, -45/90)").

Inputs follow the frame files (docs/outputs.md): the bodies block (cell arrays ply_index,
ply_angle, alive, mat054_ef/ec/em/ed) and the rigid block, as ParaView's PVD reader delivers them
(a multiblock with named blocks when a time has several parts, else the data set itself).
"""

from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkIdList, vtkPoints
from vtkmodules.vtkCommonDataModel import (vtkCompositeDataSet, vtkDataObject, vtkDataSet, vtkDataSetAttributes,
                                           vtkMultiBlockDataSet, vtkPolyData, vtkUnstructuredGrid)
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersCore import vtkAppendFilter, vtkAppendPolyData, vtkThreshold
from vtkmodules.vtkFiltersExtraction import vtkExtractCells
from vtkmodules.vtkFiltersGeneral import vtkTransformFilter
from vtkmodules.vtkRenderingFreeType import vtkVectorText

# ---------------------------------------------------------------------------- the view, as data
# Both front ends apply these: colours, camera, sizes.
DAMAGE_ARRAY = "failed_modes"
FAILURE_FLAGS = ("mat054_ef", "mat054_ec", "mat054_em", "mat054_ed")
ERODED = 5  # value of DAMAGE_ARRAY for an eroded element
DAMAGE_CATEGORIES = [  # value, RGB, label
    (0, (0.85, 0.87, 0.90), "intact"),
    (1, (0.99, 0.85, 0.35), "1 mode failed"),
    (2, (0.98, 0.55, 0.20), "2 modes"),
    (3, (0.85, 0.25, 0.15), "3 modes"),
    (4, (0.50, 0.05, 0.10), "4 modes"),
    (ERODED, (0.10, 0.10, 0.10), "eroded"),
]
INTERFACE_RANGE = (0.0, 1.0)  # interface damage
NAN_COLOUR = (0.93, 0.93, 0.93)  # C-scan: nothing delaminated there (light grey: the plate shows)
BACKGROUND = (1.0, 1.0, 1.0)
LABEL_COLOUR = (0.0, 0.0, 0.0)
WINDOW_SIZE = (1600, 1000)
COLUMNS = 4  # tiles per row
TILE_MARGIN = 0.12  # gap between tiles, as a fraction of the plate's size
LABEL_HEIGHT = 0.09  # label text height, as a fraction of the plate's width
INTERFACES_X = COLUMNS + 0.5  # first column of the interfaces' grid, in tiles (right of the plies)
CSCAN_X = -1.5  # column of the C-scan tile (left of the plies)
INTERFACE_ARRAY = ("POINTS", "damage")  # 0 intact ... 1 separated
CSCAN_ARRAYS = ("depth_shallowest", "depth", "damage")  # preferred colouring of cscan.vtu


# ---------------------------------------------------------------------------- blocks
def on_reference(data):
    """`data` with its points moved back by its point array `displacement` (as it is if it has
    none): a damage map drawn where the material was. In the deformed frames the nodes only eroded
    elements held fly off unrestrained (and the interface pairs of those plies with them), and
    their bounds would set the tiles' size."""
    u = data.GetPointData().GetArray("displacement") if data is not None else None
    if u is None or data.GetNumberOfPoints() == 0:
        return data
    pts = vtkPoints()
    pts.SetDataTypeToDouble()
    pts.SetNumberOfPoints(data.GetNumberOfPoints())
    for i in range(data.GetNumberOfPoints()):
        x, d = data.GetPoint(i), u.GetTuple3(i)
        pts.SetPoint(i, x[0] - d[0], x[1] - d[1], x[2] - d[2])
    ref = data.NewInstance()
    ref.ShallowCopy(data)
    ref.SetPoints(pts)
    return ref


def reference_bodies(frame):
    """The bodies block on its reference geometry (on_reference), or None."""
    return on_reference(named_blocks(frame).get("bodies"))


def named_blocks(data):
    """{name: data set} of a frame: the blocks of a multiblock by their NAME (the first leaf data
    set under each), or {"bodies": data} for a plain data set."""
    if data is None:
        return {}
    if isinstance(data, vtkDataSet) or not data.IsA("vtkMultiBlockDataSet"):
        return {"bodies": data}
    out = {}
    for i in range(data.GetNumberOfBlocks()):
        meta = data.GetMetaData(i) if data.HasMetaData(i) else None
        name = meta.Get(vtkCompositeDataSet.NAME()) if meta is not None else None
        leaf = _first_leaf(data.GetBlock(i))
        if leaf is not None:
            out[name or "block%d" % i] = leaf
    return out


def _first_leaf(block):
    if block is None:
        return None
    if isinstance(block, vtkDataSet):
        return block
    if block.IsA("vtkMultiBlockDataSet") or block.IsA("vtkMultiPieceDataSet"):
        for i in range(block.GetNumberOfBlocks() if block.IsA("vtkMultiBlockDataSet") else block.GetNumberOfPieces()):
            leaf = _first_leaf(block.GetBlock(i) if block.IsA("vtkMultiBlockDataSet") else block.GetPiece(i))
            if leaf is not None:
                return leaf
    return None


# ---------------------------------------------------------------------------- helpers
def _threshold(data, array, lo, hi):
    t = vtkThreshold()
    t.SetInputData(data)
    t.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_CELLS, array)
    t.SetLowerThreshold(lo)
    t.SetUpperThreshold(hi)
    t.SetThresholdFunction(vtkThreshold.THRESHOLD_BETWEEN)
    t.Update()
    return t.GetOutput()


def _moved(data, dx, dy, dz):
    tr = vtkTransform()
    tr.Translate(dx, dy, dz)
    f = vtkTransformFilter()
    f.SetTransform(tr)
    f.SetInputData(data)
    f.Update()
    return f.GetOutput()


def _over_plate(data, bounds):
    """The cells of `data` whose points all lie over the plate's reference area (bounds, 1 %
    margin): interface frames written before they had a `displacement` array cannot be moved back,
    and the pairs of plies eroded under an impactor fly off with their nodes."""
    mx, my = 0.01 * (bounds[1] - bounds[0]), 0.01 * (bounds[3] - bounds[2])
    inside = [bounds[0] - mx <= p[0] <= bounds[1] + mx and bounds[2] - my <= p[1] <= bounds[3] + my
              for p in (data.GetPoint(i) for i in range(data.GetNumberOfPoints()))]
    keep = vtkIdList()
    for c in range(data.GetNumberOfCells()):
        ids = data.GetCell(c).GetPointIds()
        if all(inside[ids.GetId(j)] for j in range(ids.GetNumberOfIds())):
            keep.InsertNextId(c)
    if keep.GetNumberOfIds() == data.GetNumberOfCells():
        return data
    extract = vtkExtractCells()
    extract.SetInputData(data)
    extract.SetCellList(keep)
    extract.Update()
    return extract.GetOutput()


def _int_range(data, array):
    a = data.GetCellData().GetArray(array)
    if a is None or a.GetNumberOfTuples() == 0:
        return []
    lo, hi = a.GetRange(0)
    return list(range(int(round(lo)), int(round(hi)) + 1))


def _label(text, x, y, height):
    v = vtkVectorText()
    v.SetText(text)
    v.Update()
    poly = v.GetOutput()
    b = poly.GetBounds()
    scale = height / max(b[3] - b[2], 1e-30)
    tr = vtkTransform()
    tr.Translate(x, y, 0.0)
    tr.Scale(scale, scale, scale)
    f = vtkTransformFilter()
    f.SetTransform(tr)
    f.SetInputData(poly)
    f.Update()
    return f.GetOutput()


def with_damage_count(grid):
    """Adds the cell array DAMAGE_ARRAY: failed modes 0-4 of a live element, ERODED for an eroded
    one. Computed in Python rather than with a calculator so that NaN (cells without *MAT_054)
    stays NaN (drawn in the NaN colour)."""
    cd = grid.GetCellData()
    flags = [cd.GetArray(n) for n in FAILURE_FLAGS]
    alive = cd.GetArray("alive")
    out = vtkDoubleArray()
    out.SetName(DAMAGE_ARRAY)
    n = grid.GetNumberOfCells()
    out.SetNumberOfTuples(n)
    have_flags = all(f is not None for f in flags)
    for c in range(n):
        if alive is not None and alive.GetValue(c) == 0:
            out.SetValue(c, ERODED)
        elif have_flags:
            out.SetValue(c, 4.0 - sum(f.GetValue(c) for f in flags))
        else:
            out.SetValue(c, float("nan"))
    cd.AddArray(out)
    return grid


def _tile_pitch(bounds):
    lx, ly = bounds[1] - bounds[0], bounds[3] - bounds[2]
    return lx * (1 + TILE_MARGIN), ly * (1 + TILE_MARGIN + 2 * LABEL_HEIGHT)


# ---------------------------------------------------------------------------- the view's pieces
def ply_tiles(frame):
    """The plies of the bodies block side by side (ply 1 at the top left, rows of COLUMNS), each
    moved so its reference plane is z = 0, with DAMAGE_ARRAY, on the reference geometry; eroded
    elements are kept (marked). An empty grid when the frame has no ply_index array."""
    bodies = reference_bodies(frame)
    out = vtkUnstructuredGrid()
    if bodies is None or bodies.GetCellData().GetArray("ply_index") is None:
        return out
    b = bodies.GetBounds()
    px, py = _tile_pitch(b)
    append = vtkAppendFilter()
    k = 0
    for ply in _int_range(bodies, "ply_index"):
        if ply <= 0:
            continue
        one = _threshold(bodies, "ply_index", ply - 0.5, ply + 0.5)
        if one.GetNumberOfCells() == 0:
            continue
        zb = one.GetBounds()
        append.AddInputData(_moved(one, (k % COLUMNS) * px, -(k // COLUMNS) * py, -zb[5]))
        k += 1
    if k == 0:
        return out
    append.Update()
    out.ShallowCopy(append.GetOutput())
    return with_damage_count(out)


def interface_tiles(interfaces, plate_bounds):
    """The interfaces (interfaces.pvd at the same time: one named block per interface, point data
    `damage`) as a second grid to the right of the plies' grid, each flattened to z = 0."""
    out = vtkUnstructuredGrid()
    blocks = [b for b in named_blocks(interfaces).values() if b.GetNumberOfCells() > 0]
    if not blocks:
        return out
    px, py = _tile_pitch(plate_bounds)
    append = vtkAppendFilter()
    for k, block in enumerate(blocks):
        block = _over_plate(on_reference(block), plate_bounds)
        zb = block.GetBounds()
        append.AddInputData(_moved(block, INTERFACES_X * px + (k % COLUMNS) * px, -(k // COLUMNS) * py, -zb[5]))
    append.Update()
    out.ShallowCopy(append.GetOutput())
    return out


def cscan_tile(cscan, plate_bounds):
    """The projected delamination map (cscan.vtu, cell data depth_shallowest) to the left of the
    plies' grid, at z = 0."""
    out = vtkUnstructuredGrid()
    if cscan is None or cscan.GetNumberOfCells() == 0:
        return out
    px, _ = _tile_pitch(plate_bounds)
    zb = cscan.GetBounds()
    append = vtkAppendFilter()
    append.AddInputData(_moved(cscan, CSCAN_X * px, 0.0, -zb[5]))
    append.Update()
    out.ShallowCopy(append.GetOutput())
    return out


def tile_labels(frame, interfaces=None, cscan=None):
    """Labels under every tile: "ply <n>  <angle>", the interfaces' block names, "C-scan"."""
    bodies = reference_bodies(frame)
    out = vtkPolyData()
    if bodies is None:
        return out
    b = bodies.GetBounds()
    px, py = _tile_pitch(b)
    height = LABEL_HEIGHT * (b[3] - b[2])
    append = vtkAppendPolyData()

    def label(text, x, row):
        append.AddInputData(_label(text, b[0] + x, b[2] - row * py - 1.6 * height, height))

    k = 0
    if bodies.GetCellData().GetArray("ply_index") is not None:
        for ply in _int_range(bodies, "ply_index"):
            if ply <= 0:
                continue
            one = _threshold(bodies, "ply_index", ply - 0.5, ply + 0.5)
            if one.GetNumberOfCells() == 0:
                continue
            angle = one.GetCellData().GetArray("ply_angle")
            text = "ply %d" % ply
            if angle is not None and angle.GetValue(0) == angle.GetValue(0):  # not NaN
                text += "  %g" % round(angle.GetValue(0), 1)
            label(text, (k % COLUMNS) * px, k // COLUMNS)
            k += 1
    names = [n for n, blk in named_blocks(interfaces).items() if blk.GetNumberOfCells() > 0] if interfaces else []
    for i, name in enumerate(names):
        label(name.replace("_", " "), INTERFACES_X * px + (i % COLUMNS) * px, i // COLUMNS)
    if cscan is not None and cscan.GetNumberOfCells() > 0:
        label("C-scan: shallowest depth", CSCAN_X * px, 0)
    if append.GetNumberOfInputConnections(0) == 0:
        return out
    append.Update()
    out.ShallowCopy(append.GetOutput())
    return out


def colour_array(data, preferred=CSCAN_ARRAYS):
    """(association, name) of the array to colour a data set by: the first array whose name
    contains one of `preferred` (in that order), else the first scalar array; None when none."""
    for assoc, attr in (("CELLS", data.GetCellData()), ("POINTS", data.GetPointData())):
        for word in preferred:
            for i in range(attr.GetNumberOfArrays()):
                name = attr.GetArrayName(i)
                if name and word in name.lower() and attr.GetArray(i) is not None:
                    return assoc, name
    for assoc, attr in (("CELLS", data.GetCellData()), ("POINTS", data.GetPointData())):
        for i in range(attr.GetNumberOfArrays()):
            if attr.GetArray(i) is not None and attr.GetArray(i).GetNumberOfComponents() == 1:
                return assoc, attr.GetArrayName(i)
    return None


def plate_bounds(frame):
    bodies = reference_bodies(frame)
    return bodies.GetBounds() if bodies is not None else (0, 1, 0, 1, 0, 1)

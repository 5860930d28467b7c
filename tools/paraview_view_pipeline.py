"""The pipeline of tools/paraview_view.py, in plain VTK so that both front ends run the same code:
ParaView calls these functions from Programmable Filters (its Python ships the same vtkmodules),
the VTK-only renderer calls them directly.

The view: every ply of the last frame (or the chosen time) seen from above, side by side in a grid
(ply 1, the bottom ply, first), coloured by how many of its four *MAT_054 failure modes have
failed (0-4) and with eroded elements marked; then, when the result folder has them, the
interfaces (interfaces.pvd: damage of each tiebreak interface) in a second grid and the projected
delamination map (cscan.vtu). Each tile is labelled ("ply 3  -45").

Inputs follow the frame files (docs/outputs.md): the bodies block (cell arrays ply_index,
ply_angle, alive, mat054_ef/ec/em/ed) and the rigid block, as ParaView's PVD reader delivers them
(a multiblock with named blocks when a time has several parts, else the data set itself).
"""

from vtkmodules.vtkCommonCore import vtkDoubleArray
from vtkmodules.vtkCommonDataModel import (vtkCompositeDataSet, vtkDataObject, vtkDataSet, vtkDataSetAttributes,
                                           vtkMultiBlockDataSet, vtkPolyData, vtkUnstructuredGrid)
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersCore import vtkAppendFilter, vtkAppendPolyData, vtkThreshold
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
BACKGROUND = (1.0, 1.0, 1.0)
LABEL_COLOUR = (0.0, 0.0, 0.0)
WINDOW_SIZE = (1600, 1000)
COLUMNS = 4  # tiles per row
TILE_MARGIN = 0.12  # gap between tiles, as a fraction of the plate's size
LABEL_HEIGHT = 0.09  # label text height, as a fraction of the plate's width


# ---------------------------------------------------------------------------- blocks
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
    moved so its reference plane is z = 0, with DAMAGE_ARRAY; eroded elements are kept (marked).
    An empty grid when the frame has no ply_index array."""
    bodies = named_blocks(frame).get("bodies")
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


def ply_labels(frame):
    """Labels "ply <n>  <angle>" under each tile of ply_tiles, as polygons (vtkVectorText)."""
    bodies = named_blocks(frame).get("bodies")
    out = vtkPolyData()
    if bodies is None or bodies.GetCellData().GetArray("ply_index") is None:
        return out
    b = bodies.GetBounds()
    px, py = _tile_pitch(b)
    height = LABEL_HEIGHT * (b[3] - b[2])
    append = vtkAppendPolyData()
    k = 0
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
        append.AddInputData(_label(text, b[0] + (k % COLUMNS) * px, b[2] - (k // COLUMNS) * py - 1.6 * height, height))
        k += 1
    if k == 0:
        return out
    append.Update()
    out.ShallowCopy(append.GetOutput())
    return out


def _interface_ids(data):
    for attr in (data.GetCellData(), data.GetPointData()):
        if attr.GetArray("interface_id") is not None:
            return attr
    return None


def interface_tiles(interfaces, plate_bounds):
    """The interfaces (interfaces.pvd's data at the same time) as a second grid to the right of the
    plies' grid, one tile per interface_id when the data has that array, flattened to z = 0."""
    data = named_blocks(interfaces)
    out = vtkUnstructuredGrid()
    if not data:
        return out
    surface = next(iter(data.values()))
    px, py = _tile_pitch(plate_bounds)
    x0 = (COLUMNS + 0.5) * px
    append = vtkAppendFilter()
    attr = _interface_ids(surface)
    if attr is None:
        zb = surface.GetBounds()
        append.AddInputData(_moved(surface, x0, 0.0, -zb[5]))
    else:
        k = 0
        for i in _range_of(attr.GetArray("interface_id")):
            one = _threshold_any(surface, attr is surface.GetCellData(), "interface_id", i)
            if one.GetNumberOfCells() == 0:
                continue
            zb = one.GetBounds()
            append.AddInputData(_moved(one, x0 + (k % COLUMNS) * px, -(k // COLUMNS) * py, -zb[5]))
            k += 1
        if k == 0:
            return out
    append.Update()
    out.ShallowCopy(append.GetOutput())
    return out


def _range_of(array):
    lo, hi = array.GetRange(0)
    return range(int(round(lo)), int(round(hi)) + 1)


def _threshold_any(data, on_cells, array, value):
    t = vtkThreshold()
    t.SetInputData(data)
    assoc = vtkDataObject.FIELD_ASSOCIATION_CELLS if on_cells else vtkDataObject.FIELD_ASSOCIATION_POINTS
    t.SetInputArrayToProcess(0, 0, 0, assoc, array)
    t.SetLowerThreshold(value - 0.5)
    t.SetUpperThreshold(value + 0.5)
    t.SetThresholdFunction(vtkThreshold.THRESHOLD_BETWEEN)
    t.SetAllScalars(1)
    t.Update()
    return t.GetOutput()


def cscan_tile(cscan, plate_bounds):
    """The projected delamination map (cscan.vtu) below the plies' grid, at z = 0."""
    out = vtkUnstructuredGrid()
    if cscan is None or cscan.GetNumberOfCells() == 0:
        return out
    px, py = _tile_pitch(plate_bounds)
    zb = cscan.GetBounds()
    moved = _moved(cscan, (COLUMNS + 0.5) * px, -4 * py, -zb[5])
    append = vtkAppendFilter()
    append.AddInputData(moved)
    append.Update()
    out.ShallowCopy(append.GetOutput())
    return out


def colour_array(data, preferred=("damage", "delamination", "delaminated", "depth")):
    """(association, name) of the array to colour an interface or C-scan data set by: the first
    array whose name contains one of `preferred`, else the first array; None when it has none."""
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
    bodies = named_blocks(frame).get("bodies")
    return bodies.GetBounds() if bodies is not None else (0, 1, 0, 1, 0, 1)

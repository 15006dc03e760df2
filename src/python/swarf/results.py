"""What `swarf run` writes, read back: swarf.load(DIR) and swarf.run(...) (docs/python.md).

    import swarf
    summary = swarf.run("case.toml", out="a", set=["integrator.end_time=2e-5"])  # summary.json as a dict
    r = swarf.load("a")
    r.summary["cutting"]                  # summary.json
    r.series["time"], r.units["time"]     # series.csv as a NumPy structured array; units from series_columns.csv
    r.dataframe()                         # the same as a pandas DataFrame (when pandas is installed)
    r.times                               # the frames' times, s (results.h5 /frame_time)
    f = r.frame(-1)                       # the last frame: f.time, f.position (n, 3), f.id (n,), f.fields["..."]
    r.field("von_mises_stress")           # one field over the frames: a list of arrays
    r.chip_surface                        # ChipSurface (path, points, triangles) or None

The frames' fields come from results.h5 (h5py), /frames/NNNNN: the ParaView frames' point
arrays with their units, the same values as frames/particles_NNNNN.vtu. A particle keeps its
id across frames (its row may change: inflows, outflows, reordering); match rows by id.
"""
import base64
import csv
import json
import os
import struct
import xml.etree.ElementTree as ET
import zlib

import numpy as np

from ._swarf import run as _run_program

__all__ = ["load", "run", "Run", "Frame", "ChipSurface"]


def run(case=None, out=None, set=(), threads=0, restart=None, energy_check=True,  # noqa: A002 ('set': --set)
        before=None, after=None):
    """Runs a case as 'swarf run' does, every output in 'out', and returns its summary.json as a dict.

    case: a case file (None: the built-in default cut); out: the run directory (None: as the
    program: 'swarf-out', or the checkpoint's directory on a restart); set: 'key=value'
    overrides; threads: 0 for OpenMP's default; restart: a checkpoint to continue; before,
    after: functions f(step) called around every step, step a swarf.RunStep (time, steps,
    last_dt, broken_rods, mesh_names, mesh_force(name)); an exception raised in one stops the run.
    swarf.load(out) reads the rest (series, frames, chip surface).
    """
    _run_program(case, out, list(set), threads, restart, energy_check, before, after)
    if out is None:
        out = (os.path.dirname(os.fspath(restart)) or ".") if restart is not None else "swarf-out"
    with open(os.path.join(os.fspath(out), "summary.json")) as f:
        return json.load(f)


class Frame:
    """One frame of the field history: time (s), position (n, 3) m, id (n,), fields {name: array}, units."""

    def __init__(self, number, time, position, ids, fields, units):
        self.number = number
        self.time = time
        self.position = position
        self.id = ids
        self.fields = fields
        self.units = units

    def __repr__(self):
        return f"Frame({self.number}, t={self.time:.6g} s, {len(self.id)} particles, fields {sorted(self.fields)})"


class ChipSurface:
    """The chip's surface mesh (chip_surface.vtp): path, points (m, 3) m, triangles (k, 3) indices."""

    def __init__(self, path):
        self.path = path
        self.points, self.triangles = _read_vtp(path)

    def __repr__(self):
        return f"ChipSurface({self.path!r}, {len(self.points)} points, {len(self.triangles)} triangles)"


class Run:
    """A finished run directory, read by swarf.load(DIR)."""

    def __init__(self, directory):
        self.directory = os.fspath(directory)
        summary = os.path.join(self.directory, "summary.json")
        if not os.path.isfile(summary):
            raise FileNotFoundError(f"{summary} does not exist: the run in '{self.directory}' did not finish "
                                    f"(or this is not a run directory)")
        with open(summary) as f:
            self.summary = json.load(f)
        self.series = _read_series(os.path.join(self.directory, "series.csv"))
        self.units, self.meanings = _read_columns(os.path.join(self.directory, "series_columns.csv"))
        self._results = os.path.join(self.directory, "results.h5")
        self.times = np.zeros(0)
        if os.path.isfile(self._results):
            h5py = _h5py()
            with h5py.File(self._results, "r") as f:
                if "frame_time" in f:
                    self.times = f["frame_time"][...]
                    self._groups = sorted(f["frames"].keys())
        surface = self.summary.get("chip", {}).get("surface_file")
        self._surface_path = os.path.join(self.directory, surface) if surface else None
        self._surface = None

    def __repr__(self):
        return (f"Run({self.directory!r}: {len(self.series)} series rows, {len(self.times)} frames"
                f"{', chip surface' if self._surface_path else ''})")

    def dataframe(self):
        """series.csv as a pandas DataFrame (ImportError without pandas)."""
        import pandas
        return pandas.DataFrame(self.series)

    @property
    def frames(self):
        """Every frame of the field history (read from results.h5 at each access)."""
        return [self.frame(k) for k in range(len(self.times))]

    def frame(self, k):
        """Frame k of the field history (negative k counts from the end)."""
        if not len(self.times):
            raise IndexError(f"{self._results} holds no frames (output.vtk = false, or a run before layout 5)")
        k = range(len(self.times))[k]
        h5py = _h5py()
        with h5py.File(self._results, "r") as f:
            g = f["frames"][self._groups[k]]
            fields = {name: g[name][...] for name in g if name not in ("position", "id")}
            units = {name: _text(g[name].attrs.get("unit", "")) for name in g}
            return Frame(int(self._groups[k]), float(g.attrs["time_s"]), g["position"][...], g["id"][...], fields,
                         units)

    def frame_at(self, time):
        """The frame nearest to 'time' (s)."""
        return self.frame(int(np.argmin(np.abs(self.times - time))))

    def field(self, name):
        """One field over the frames: a list of arrays, one per frame (rows as the frame's ids)."""
        return [f.fields[name] for f in self.frames]

    @property
    def chip_surface(self):
        """The chip's surface (ChipSurface) if the run wrote one (summary['chip']['surface_file']), else None."""
        if self._surface is None and self._surface_path and os.path.isfile(self._surface_path):
            self._surface = ChipSurface(self._surface_path)
        return self._surface


def load(directory):
    """Reads a finished run directory: summary, series, field history, chip surface (see Run)."""
    return Run(directory)


def _h5py():
    try:
        import h5py
    except ImportError as e:  # (Debian: python3-h5py, which the .deb depends on)
        raise ImportError("swarf.load reads results.h5 with h5py: install python3-h5py (or pip install h5py)") from e
    return h5py


def _text(v):
    return v.decode() if isinstance(v, bytes) else str(v)


def _read_series(path):
    """series.csv (one header row, then numbers) as a structured array of float64 columns."""
    with open(path, newline="") as f:
        reader = csv.reader(f)
        names = next(reader)
        rows = [tuple(float(x) for x in r) for r in reader if r]
    return np.array(rows, dtype=[(n, "f8") for n in names])


def _read_columns(path):
    """series_columns.csv: ({column: unit}, {column: meaning}); empty when the file is missing."""
    if not os.path.isfile(path):
        return {}, {}
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {r["column"]: r["unit"] for r in rows}, {r["column"]: r["meaning"] for r in rows}


def _vtk_array(element, header_type, compressed):
    """The values of a VTK XML DataArray written as swarf writes them (format="binary", base64,
    optionally zlib-compressed with a block header of 'header_type' integers)."""
    dtypes = {"Float32": "<f4", "Float64": "<f8", "Int32": "<i4", "Int64": "<i8", "UInt8": "u1", "UInt32": "<u4",
              "UInt64": "<u8", "Int8": "i1"}
    dtype = np.dtype(dtypes[element.get("type")])
    text = "".join((element.text or "").split())
    if element.get("format") != "binary":
        return np.array((element.text or "").split(), dtype=dtype)
    h = "<Q" if header_type == "UInt64" else "<I"
    hs = struct.calcsize(h)
    if not compressed:
        raw = base64.b64decode(text)
        n = struct.unpack(h, raw[:hs])[0]
        return np.frombuffer(raw[hs:hs + n], dtype=dtype)
    # Compressed: base64(header [blocks, block size, last block size, compressed sizes...]) then
    # base64(the compressed blocks), each encoded on its own.
    first = base64.b64decode(text[:4 * ((3 * hs + 2) // 3)])
    blocks = struct.unpack("<" + h[1] * 3, first[:3 * hs])[0]
    header_len = 4 * (((3 + blocks) * hs + 2) // 3)
    header = base64.b64decode(text[:header_len])
    sizes = struct.unpack("<" + h[1] * blocks, header[3 * hs:(3 + blocks) * hs])
    data = base64.b64decode(text[header_len:])
    out, at = [], 0
    for s in sizes:
        out.append(zlib.decompress(data[at:at + s]))
        at += s
    return np.frombuffer(b"".join(out), dtype=dtype)



def _read_vtp(path):
    """Points (m, 3) and triangles (k, 3) of a VTK XML polydata file as swarf writes it (vtk_output.cpp)."""
    root = ET.parse(path).getroot()
    header_type = root.get("header_type", "UInt32")
    compressed = root.get("compressor") is not None
    piece = root.find("PolyData/Piece")
    points = _vtk_array(piece.find("Points/DataArray"), header_type, compressed).reshape(-1, 3)
    polys = {a.get("Name"): _vtk_array(a, header_type, compressed) for a in piece.find("Polys").findall("DataArray")}
    conn, offsets = polys["connectivity"], polys["offsets"]
    if len(offsets) and not np.all(np.diff(np.concatenate([[0], offsets])) == 3):
        raise ValueError(f"{path}: polygons other than triangles")
    return points, conn.reshape(-1, 3).astype(np.int64)

"""Consistency of a dmhs output directory's XDMF index and HDF5 snapshots:
every DataItem reference resolves to a dataset of the declared dimensions and
number type, Polyvertex NumberOfElements equals the particle count, Vector
attributes have 3 components, times increase and match the snapshots' "time"
attribute, and every value is finite. Usage: check_xdmf.py DIR [min_snapshots]"""
import math
import os
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np


def fail(msg):
    print("FAIL:", msg)
    sys.exit(1)


def main(out_dir, min_snapshots=1):
    path = os.path.join(out_dir, "particles.xdmf")
    root = ET.parse(path).getroot()
    if root.tag != "Xdmf":
        fail(f"{path}: root element is {root.tag}")
    collection = root.find("Domain/Grid")
    if collection is None or collection.get("GridType") != "Collection" or collection.get("CollectionType") != "Temporal":
        fail("no temporal collection")
    grids = collection.findall("Grid")
    if len(grids) < min_snapshots:
        fail(f"{len(grids)} snapshots indexed, expected at least {min_snapshots}")
    times, files = [], set()
    n_items = 0
    for grid in grids:
        time = grid.find("Time")
        if time is None:
            fail(f"grid {grid.get('Name')} has no Time")
        t = float(time.get("Value"))
        if not math.isfinite(t):
            fail(f"grid {grid.get('Name')}: time {time.get('Value')}")
        times.append(t)
        particle_grid = grid if grid.get("GridType") == "Uniform" else grid.find("Grid[@Name='particles']")
        topo = particle_grid.find("Topology")
        if topo.get("TopologyType") != "Polyvertex":
            fail(f"t = {t}: topology {topo.get('TopologyType')}")
        n = int(topo.get("NumberOfElements"))
        geom = particle_grid.find("Geometry")
        if geom.get("GeometryType") not in ("XY", "XYZ"):
            fail(f"t = {t}: geometry type {geom.get('GeometryType')}")
        for item in grid.iter("DataItem"):
            n_items += 1
            dims = tuple(int(d) for d in item.get("Dimensions").split())
            h5name, dataset = item.text.strip().split(":", 1)
            files.add(h5name)
            with h5py.File(os.path.join(out_dir, h5name), "r") as f:
                if dataset not in f:
                    fail(f"{item.text.strip()} does not exist")
                d = f[dataset]
                if d.shape != dims:
                    fail(f"{item.text.strip()}: shape {d.shape}, XDMF says {dims}")
                kind = item.get("NumberType")
                if (kind == "Float") != (d.dtype.kind == "f") or int(item.get("Precision")) != d.dtype.itemsize:
                    fail(f"{item.text.strip()}: dtype {d.dtype}, XDMF says {kind} {item.get('Precision')}")
                data = d[()]
                if d.dtype.kind == "f" and not np.all(np.isfinite(data)):
                    fail(f"{item.text.strip()}: non-finite values")
                if not f.attrs["time"][0] == t:  # (abs(nan - t) > 0 is false: a NaN passed)
                    fail(f"{h5name}: time attribute {f.attrs['time'][0]} != XDMF time {t}")
                if dataset.startswith("/particles/") and dims[0] != n:
                    fail(f"{item.text.strip()}: {dims[0]} rows but NumberOfElements = {n}")
        for attr in particle_grid.findall("Attribute"):
            dims = tuple(int(d) for d in attr.find("DataItem").get("Dimensions").split())
            want = {"Scalar": 1, "Vector": 2}[attr.get("AttributeType")]
            if len(dims) != want or (want == 2 and dims[1] != 3):
                fail(f"attribute {attr.get('Name')}: {attr.get('AttributeType')} with dimensions {dims}")
    if any(b <= a for a, b in zip(times, times[1:])):
        fail(f"times not increasing: {times}")
    # every snapshot file in the directory is indexed
    on_disk = {f for f in os.listdir(out_dir) if f.startswith("snap_") and f.endswith(".h5")}
    if on_disk != files:
        fail(f"snapshot files not indexed or missing: {sorted(on_disk ^ files)}")
    print(f"{path}: {len(grids)} snapshots, t = {times[0]} .. {times[-1]} s, {n_items} data items, all consistent")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 1))

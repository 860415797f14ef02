# SPDX-License-Identifier: LGPL-2.1-or-later
"""Helper of the test output_hdf5: reads back what OutputWriter wrote.

compare VTU H5     every point field of the HDF5 file H5 against the VTU file VTU of the same step
series DIRECTORY   the steps that DIRECTORY/solution.xdmf lists, and whether each entry matches its .h5 file

Prints only stable facts (counts, names, yes/no); reads VTU files (zlib-compressed base64, Float32) without VTK.
"""
import base64
import struct
import sys
import xml.etree.ElementTree as ET
import zlib

import h5py
import numpy as np


def vtu_array(element):
    """The values of one <DataArray format="binary"> of a compressed VTU file (UInt32 headers), as float64."""
    text = element.text.strip()
    n_blocks = struct.unpack("<I", base64.b64decode(text[:8])[:4])[0]
    header_chars = 4 * ((4 * (3 + n_blocks) + 2) // 3)
    header = struct.unpack(f"<{3 + n_blocks}I", base64.b64decode(text[:header_chars]))
    data, offset = base64.b64decode(text[header_chars:]), 0
    raw = b""
    for size in header[3:]:
        raw += zlib.decompress(data[offset:offset + size])
        offset += size
    dtype = {"Float32": "<f4", "Float64": "<f8", "Int32": "<i4", "UInt8": "u1"}[element.get("type")]
    values = np.frombuffer(raw, dtype=dtype).astype(np.float64)
    return values.reshape(-1, int(element.get("NumberOfComponents", "1")))


def read_vtu(name):
    """Points, cell connectivity (global point indices) and point fields of all pieces of a VTU file."""
    pieces = ET.parse(name).getroot().iter("Piece")
    points, connectivity, fields = [], [], {}
    for piece in pieces:
        connectivity.append(vtu_array(piece.find("Cells/DataArray[@Name='connectivity']")) + sum(map(len, points)))
        points.append(vtu_array(piece.find("Points/DataArray")))
        for array in piece.find("PointData"):
            fields.setdefault(array.get("Name"), []).append(vtu_array(array))
    return np.vstack(points), np.vstack(connectivity), {k: np.vstack(v) for k, v in fields.items()}


def compare(vtu_name, h5_name):
    points, connectivity, fields = read_vtu(vtu_name)
    with h5py.File(h5_name, "r") as h5:
        nodes = h5["nodes"][:]
        cells = h5["cells"][:]
        h5_fields = {k: h5[k][:] for k in h5 if k not in ("nodes", "cells")}
    # Each VTU point (curved sub-cell corners, shared ones repeated) is matched with the nearest HDF5 node.
    distance = np.linalg.norm(points[:, None, :] - nodes[None, :, :], axis=2)
    match = distance.argmin(axis=1)
    tolerance = 1e-6 * np.abs(nodes).max()
    # Cells compared through their centroids: the HDF5 cells must be the VTU cells, one to one.
    vtu_cells = connectivity.reshape(-1, 4).astype(int)
    centroid_distance = np.linalg.norm(points[vtu_cells].mean(axis=1)[:, None, :]
                                       - nodes[cells.astype(int)].mean(axis=1)[None, :, :], axis=2)
    print(f"VTU points {len(points)}, HDF5 nodes {len(nodes)}, HDF5 cells {len(cells)} of {cells.shape[1]} vertices")
    print(f"every VTU point at an HDF5 node and every HDF5 node at a VTU point: "
          f"{'yes' if distance.min(axis=1).max() < tolerance and distance.min(axis=0).max() < tolerance else 'no'}")
    print(f"the HDF5 cells are the VTU cells: "
          f"{'yes' if len(vtu_cells) == len(cells) and centroid_distance.min(axis=1).max() < tolerance and len(set(centroid_distance.argmin(axis=1))) == len(cells) else 'no'}")
    print(f"same fields: {'yes' if sorted(fields) == sorted(h5_fields) else 'no'} ({', '.join(sorted(h5_fields))})")
    for name in sorted(h5_fields):
        if name not in fields:
            continue
        h5_values, vtu_values = h5_fields[name][match], fields[name]
        magnitude = max(np.abs(h5_values).max(), 1e-300)
        # The VTU holds Float32: agreement means |difference| ≤ 2⁻²³·max|value| (single precision rounding).
        error = np.abs(h5_values - vtu_values).max() / magnitude
        print(f"  {name} ({h5_values.shape[1]} components): "
              f"{'agree to float32 rounding' if error <= 2.0**-23 else 'DIFFER'}")


def series(directory):
    root = ET.parse(directory + "/solution.xdmf").getroot()
    steps = root.findall("Domain/Grid/Grid")
    names, times, consistent = [], [], True
    for grid in steps:
        topology = grid.find("Topology")
        h5_name = grid.find("Geometry/DataItem").text.strip().split(":")[0]
        names.append(h5_name.replace("solution-", "").replace(".h5", ""))
        times.append(float(grid.find("Time").get("Value")))
        with h5py.File(directory + "/" + h5_name, "r") as h5:
            n_nodes, n_cells = len(h5["nodes"]), len(h5["cells"])
            consistent &= topology.get("TopologyType") == "Quadrilateral"
            consistent &= int(topology.get("NumberOfElements")) == n_cells
            for item in grid.iter("DataItem"):
                path = item.text.strip().split(":/")[1]
                consistent &= [int(d) for d in item.get("Dimensions").split()][0] == len(h5[path])
                consistent &= path in ("nodes", "cells") or len(h5[path]) == n_nodes
    in_order = all(a < b for a, b in zip(times, times[1:]))
    once = len(set(names)) == len(names) and names == [f"{i:05d}" for i in range(len(names))]
    print(f"{directory}/solution.xdmf: {len(steps)} steps, files {' '.join(names)}")
    print(f"  times {' '.join(f'{t:g}' for t in times)}")
    print(f"  each step once, in order: {'yes' if in_order and once else 'no'}; "
          f"Quadrilateral topology and sizes match the .h5 files: {'yes' if consistent else 'no'}")


if __name__ == "__main__":
    if sys.argv[1] == "compare":
        compare(sys.argv[2], sys.argv[3])
    else:
        series(sys.argv[2])

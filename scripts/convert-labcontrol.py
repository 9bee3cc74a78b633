#!/usr/bin/env python3
"""Converts the shaking-table MR damper tests of labcontrol-data/mr-damper (A. N. Vargas, UTFPR,
MIT licence, doi:10.5281/zenodo.4445334) into rheomag recordings (CSV + TOML sidecar,
docs of the recording format in ../shared/docs/recording-format.md).

Usage: scripts/convert-labcontrol.py MR_DAMPER_CHECKOUT OUTPUT_DIR

Each test's MATLAB file holds x_F = [position mm, velocity mm/s, force N] at Ts = 0.01 s. The coil
voltage is constant per test and not in the file; the lab's spreadsheet (data/Ensaios.ods) gives
it per series: ensaioK.1 at 0 V, ensaioK.2 at 0.8712 V, ensaio.B.K at 1.98 V, ensaio.A.K at
3.212 V. The current is estimated from the one current the spreadsheet quotes (0.495 A at
3.212 V). Only the Python standard library is used (a MAT v5 reader for real double matrices).
"""
import os
import struct
import sys
import zlib

SERIES = {  # file stem -> (recording prefix, coil voltage [V])
    **{f"ensaio{k}.1": (f"0V_test{k}_1", 0.0) for k in range(1, 11)},
    **{f"ensaio{k}.2": (f"0x87V_test{k}_2", 0.8712) for k in range(1, 11)},
    **{f"ensaio.B.{k}": (f"1x98V_test_B_{k}", 1.98) for k in (1, 3, 5, 6, 7, 8, 9, 10)},
    **{f"ensaio.A.{k}": (f"3x21V_test_A_{k}", 3.212) for k in range(1, 11)},
}
AMPERE_PER_VOLT = 0.495 / 3.212
MI_INT8, MI_DOUBLE, MI_MATRIX, MI_COMPRESSED = 1, 9, 14, 15


def elements(buf, pos, end):
    """Yields (type, payload) of the data elements in buf[pos:end]."""
    while pos + 8 <= end:
        kind, size = struct.unpack_from("<II", buf, pos)
        if kind >> 16:  # small element: size and type share the tag
            yield kind & 0xFFFF, buf[pos + 4:pos + 4 + (kind >> 16)]
            pos += 8
            continue
        yield kind, buf[pos + 8:pos + 8 + size]
        pos += 8 + size + (0 if kind == MI_COMPRESSED else (8 - size % 8) % 8)


def real_matrices(path):
    """The real double matrices of a MAT v5 file: name -> (rows, cols, column-major values)."""
    buf = open(path, "rb").read()
    out = {}
    for kind, payload in elements(buf, 128, len(buf)):
        if kind == MI_COMPRESSED:
            payload = zlib.decompress(payload)
            kind, size = struct.unpack_from("<II", payload, 0)
            payload = payload[8:8 + size]
        if kind != MI_MATRIX:
            continue
        parts = list(elements(payload, 0, len(payload)))
        if len(parts) < 4 or parts[3][0] != MI_DOUBLE or (parts[0][1][0] & 0xFF) != 6:
            continue  # not a real double array
        rows, cols = struct.unpack_from("<ii", parts[1][1], 0)
        name = parts[2][1].decode("latin1")
        data = parts[3][1]
        out[name] = (rows, cols, struct.unpack(f"<{len(data) // 8}d", data))
    return out


def convert(checkout, output):
    os.makedirs(output, exist_ok=True)
    for stem, (name, volts) in SERIES.items():
        source = os.path.join(checkout, "data", stem + ".mat")
        m = real_matrices(source)
        rows, cols, xf = m["x_F"]
        ts = m["Ts"][2][0]
        if cols != 3:
            sys.exit(f"{source}: x_F has {cols} columns, expected 3 (position, velocity, force)")
        current = volts * AMPERE_PER_VOLT
        with open(os.path.join(output, name + ".csv"), "w") as csv:
            csv.write("t,displacement,velocity,current,force\n")
            for i in range(rows):
                x, v, f = xf[i] * 1e-3, xf[rows + i] * 1e-3, xf[2 * rows + i]
                csv.write(f"{i * ts:.2f},{x:.6g},{v:.6g},{current:.4g},{f:.6g}\n")
        with open(os.path.join(output, name + ".toml"), "w") as toml:
            toml.write(f"# source: A. N. Vargas, labcontrol-data/mr-damper (MIT), data/{stem}.mat, x_F\n")
            toml.write("[recording]\n")
            toml.write(f'description = "MR damper on a small shaking table (UTFPR Labcontrol), '
                       f'sinusoid, coil at {volts} V (current estimated as V x 0.495/3.212 A/V), '
                       f'velocity derived from the displacement, force with the load cell\'s zero"\n')
            toml.write('drive = ["displacement", "velocity", "current"]\noutput = "force"\n\n')
            toml.write('[rig]\nkind = "damper"\n')


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    convert(sys.argv[1], sys.argv[2])

# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
"""python3 Fuzz/make_corpus.py: writes the fuzzers' seed inputs in Fuzz/corpus (small, valid
inputs the fuzzer mutates; committed). Fuzz/corpus/FuzzHDF5SnapshotReader is not written here:
that target decodes its input with libFuzzer's FuzzedDataProvider, so its 40 seeds are the largest
inputs of a 6-minute run's merged corpus (-merge=1)."""
import math
import os
import random
import struct

here = os.path.dirname(os.path.abspath(__file__))


def write(target, name, data):
    folder = os.path.join(here, "corpus", target)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), "wb") as out:
        out.write(data)


# Tipsy: header (double time; int nbodies, ndim, nsph, ndark, nstar; pad), then 12 float32 per
# gas particle, 9 per dark one, 11 per star; big-endian ('>') and little-endian ('<').
for order, label in ((">", "big"), ("<", "little")):
    header = struct.pack(order + "diiiiii", 0.5, 5, 3, 2, 2, 1, 0)
    gas = b"".join(struct.pack(order + "12f", 1e-3, i, 2 * i, 3 * i, 0, 0, 0, 1.0 + i, 100, 0.1,
                               0, 0) for i in range(2))
    dark = b"".join(struct.pack(order + "9f", 1e-2, -i, i, 0, 0, 0, 0, 0.05, 0)
                    for i in range(2))
    star = struct.pack(order + "11f", 1e-4, 0.5, 0.5, 0.5, 0, 0, 0, 0.02, 0.1, 0.05, 0)
    write("FuzzTipsyReader", "mixed-" + label, header + gas + dark + star)
    write("FuzzTipsyReader", "truncated-" + label, (header + gas)[:60])
    # The header without its pad (28 bytes), as older tools wrote it.
    write("FuzzTipsyReader", "unpadded-" + label, header[:28] + gas + dark + star)
    # With auxiliary arrays (binary floats, text integers, a binary vector) and the run's
    # parameter file (a periodic box), each after its marker line.
    n = 5
    binary = struct.pack(">i", n) + struct.pack(">5f", *range(n))
    text = ("%d\n" % n + "".join("%d\n" % (7 * i) for i in range(n))).encode()
    vector = struct.pack(">i", n) + struct.pack(">15f", *range(3 * n))
    params = b"achOutName = run\nbPeriodic = 1\ndPeriod = 40\ndzPeriod = 0 # open along z\n"
    write("FuzzTipsyReader", "beside-" + label, header + gas + dark + star + b"\n#AUX\n" + binary +
          b"\n#AUX\n" + text + b"\n#AUX\n" + vector + b"\n#PARAM\n" + params)
    # Double-precision positions (ChaNGa's bDoublePos), then positions and velocities too: the
    # reader tells them from the file's size.
    for vel, name in (("3f", "double-positions-"), ("3d", "double-velocities-")):
        gas = b"".join(struct.pack(order + "f3d" + vel + "5f", 1e-3, i, 2 * i, 3 * i, 0, 0, 0,
                                   1.0 + i, 100, 0.1, 0, 0) for i in range(2))
        dark = b"".join(struct.pack(order + "f3d" + vel + "2f", 1e-2, -i, i, 0, 0, 0, 0, 0.05, 0)
                        for i in range(2))
        star = struct.pack(order + "f3d" + vel + "4f", 1e-4, 0.5, 0.5, 0.5, 0, 0, 0, 0.02, 0.1,
                           0.05, 0)
        write("FuzzTipsyReader", name + label, header + gas + dark + star)

# GADGET binary: Fortran records (length, data, length); a 256-byte header (int npart[6],
# double mass[6], time, redshift, int flag_sfr, flag_feedback, uint npartTotal[6], int
# flag_cooling, num_files, double BoxSize, Omega0, OmegaLambda, HubbleParam, ...); then POS,
# VEL, ID, MASS, U, RHO, HSML. Format 1 little-endian, format 2 (labelled) big-endian, one with
# the cooling flag and NE, NH, one saying 2 files, one with GADGET-3's INFO block.
def gadget(order, fmt, cooling=False, files=1, real="f", info=False):
    npart = [3, 2, 0, 0, 0, 0]
    head = struct.pack(order + "6i6d2d2i6I2i4d", *npart, 0, 0.5, 0, 0, 0, 0, 0.25, 0.0, 0, 0,
                       *npart, int(cooling), files, 10.0, 0.3, 0.7, 0.7)
    head += bytes(256 - len(head))
    n = sum(npart)
    blocks = [("HEAD", head),
              ("POS ", struct.pack(order + "%d%s" % (3 * n, real), *range(3 * n))),
              ("VEL ", struct.pack(order + "%d%s" % (3 * n, real), *([0] * 3 * n))),
              ("ID  ", struct.pack(order + "%dI" % n, *range(1, n + 1))),
              ("MASS", struct.pack(order + "3" + real, 1, 2, 3)),
              ("U   ", struct.pack(order + "3" + real, 1, 1, 1)),
              ("RHO ", struct.pack(order + "3" + real, 1, 2, 4))]
    if cooling:
        blocks += [("NE  ", struct.pack(order + "3" + real, 1, 1, 1)),
                   ("NH  ", struct.pack(order + "3" + real, 0, 0, 0))]
    blocks.append(("HSML", struct.pack(order + "3" + real, 0.5, 0.5, 0.5)))
    if info:  # GADGET-3's INFO: label, type, values per particle, types present
        kind = "DOUBLE" if real == "d" else "FLOAT"
        entries = [("POS ", kind + "N", 3, [1, 1, 0, 0, 0, 0]), ("ID  ", "LONG", 1, [1, 1, 0, 0, 0, 0]),
                   ("MASS", kind, 1, [1, 0, 0, 0, 0, 0]), ("RHO ", kind, 1, [1, 0, 0, 0, 0, 0])]
        blocks.insert(1, ("INFO", b"".join(label.encode() + t.ljust(8).encode() +
                                           struct.pack(order + "7i", n, *present)
                                           for label, t, n, present in entries)))
    out = b""
    for label, data in blocks:
        if fmt == 2:
            label_data = label.encode() + struct.pack(order + "i", len(data) + 8)
            out += struct.pack(order + "i", 8) + label_data + struct.pack(order + "i", 8)
        out += struct.pack(order + "i", len(data)) + data + struct.pack(order + "i", len(data))
    return out


write("FuzzGadgetBinaryReader", "format1-little", gadget("<", 1))
write("FuzzGadgetBinaryReader", "format2-big-double", gadget(">", 2, real="d"))
write("FuzzGadgetBinaryReader", "format1-cooling", gadget("<", 1, cooling=True))
write("FuzzGadgetBinaryReader", "format1-two-files", gadget("<", 1, files=2))
write("FuzzGadgetBinaryReader", "format2-info", gadget("<", 2, info=True))
# GADGET-4's own header (192 bytes: 64-bit counts and totals, masses, time, redshift, box size,
# num_files, alignment, Ntrees, TotNtrees) before the same blocks, format 1.
g4 = gadget("<", 1)
head4 = struct.pack("<6q6q6d3di4x2q", 3, 2, 0, 0, 0, 0, 3, 2, 0, 0, 0, 0, 0, 0.5, 0, 0, 0, 0,
                    0.25, 0.0, 10.0, 1, 0, 0)
write("FuzzGadgetBinaryReader", "format1-gadget4",
      struct.pack("<i", 192) + head4 + struct.pack("<i", 192) + g4[4 + 256 + 4:])

# The filter: flags, neighbours - 4, eight float64 parameters, then (x, y, z, f) float32 points
# of a ball f = 20 - |x - (30, 30, 30)| in [0, 60]^3.
rng = random.Random(7)
points = b""
for _ in range(1000):
    x = [rng.uniform(0, 60) for _ in range(3)]
    f = 20 - math.sqrt(sum((c - 30) ** 2 for c in x))
    points += struct.pack("<4f", *x, f)
# (A neighbour byte of 160 or more also re-runs: QuickIsoValueChanges, a small isovalue change,
# a SplatScale change; 182 gives the same 26 neighbours as 22.)
for flags, name, byte in ((0, "ball-splats", 22), (1 | 2, "ball-seed-spheres", 22),
                          (8, "ball-sph", 22), (16 | 1, "ball-periodic", 22),
                          (32 | 64, "ball-scheme1", 22), (0, "ball-splats-reruns", 182),
                          (8, "ball-sph-reruns", 182), (16 | 1, "ball-periodic-reruns", 182)):
    parameters = struct.pack("<8d", 0.0, 30.0, 30.0, 30.0, 8.0, 2.5, 3.0, 60.0)
    write("FuzzLevelSetIsosurface", name, struct.pack("<BB", flags, byte) + parameters + points)
print("corpus written to", os.path.join(here, "corpus"))

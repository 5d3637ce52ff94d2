#!/usr/bin/env python3
"""Writes sim/physics/exp_table.cpp: the 128-entry table of exp_lanes
(sim/physics/exp_lanes.hpp), computed here to 60 digits.

Entry k is a pair of 64-bit words: the bits of tail_k, then the bits of H_k
less k << 45, where H_k is the double nearest 2^(k/128) and tail_k the double
nearest (2^(k/128) - H_k) / H_k. Subtracting k << 45 lets the lookup add the
bits of 2^floor(k'/128) back with one integer add (exp_lanes.hpp).
Run from the repository root: scripts/make_exp_table.py
"""
import struct
from decimal import Decimal, getcontext

getcontext().prec = 60
ln2 = Decimal(2).ln()


def bits(x):
    return struct.unpack("<Q", struct.pack("<d", x))[0]


words = []
for k in range(128):
    exact = (Decimal(k) / 128 * ln2).exp()
    h = float(exact)  # Decimal -> float rounds to nearest
    tail = float((exact - Decimal(h)) / Decimal(h))
    words += [bits(tail), (bits(h) - (k << 45)) % 2**64]

lines = [f"    0x{words[i]:016x}, 0x{words[i + 1]:016x}," for i in range(0, 256, 2)]
with open("sim/physics/exp_table.cpp", "w") as out:
    out.write(
        "// Written by scripts/make_exp_table.py; do not edit. exp_lanes' table\n"
        "// (sim/physics/exp_lanes.hpp): for k = 0..127 the bits of tail_k, then the\n"
        "// bits of H_k less k << 45, H_k the double nearest 2^(k/128).\n"
        '#include "sim/physics/exp_lanes.hpp"\n\n'
        "namespace sim {\n\n"
        "const std::uint64_t kExpTable[256] = {\n" + "\n".join(lines) + "\n};\n\n"
        "}  // namespace sim\n")

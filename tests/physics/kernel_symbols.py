#!/usr/bin/env python3
"""The force kernels' object files export nothing an other instruction set could pick up.

Each variant of src/physics/ForceKernelVariant.cpp is compiled with its own -march (AVX-512 for one
of them). If such an object defined an out-of-line copy of an inline function with the same name
as the baseline's (a std::vector member, a helper of a shared header), the linker could keep the
AVX-512 copy for every caller, and the program would crash on a CPU without AVX-512. So every
global or weak symbol a variant defines must be its table function or name an entity of the
variant's own instruction-set namespace (core/Simd.h, WIGGLE_ISA_NAMESPACE): such a name, a
function of that namespace or a template instantiated with one of its types, exists in that
variant only. (Optimised builds inline everything and export the table alone; the sanitizer build,
at -O1, exports its namespace's helpers too.) The exceptions are data, the same bytes in every
object and no code: the linker's DW.ref.* (a pointer to the exception personality routine), and the
type information that clang's UBSan (-fsanitize=function) emits for the types of the functions whose
address is taken ("typeinfo for", "typeinfo name for").

usage: kernel_symbols.py NAME=OBJECT ... (NAME: scalar, avx2, avx512)
"""
import subprocess
import sys

NAMESPACE = {"scalar": "isa_baseline", "avx2": "isa_avx", "avx512": "isa_avx512"}
DATA = ("DW.ref.", "typeinfo for ", "typeinfo name for ")  # data only, the same bytes in every object


def exported(obj):
    out = subprocess.run(["nm", "-C", "--defined-only", obj], check=True, capture_output=True, text=True).stdout
    for line in out.splitlines():
        parts = line.split(" ", 2)
        if len(parts) == 3 and parts[1] not in "tdbrn":  # lower case: local to the object
            yield parts[2]


def main(args):
    if not args:
        sys.exit("usage: kernel_symbols.py NAME=OBJECT ...")
    bad = []
    for arg in args:
        name, obj = arg.split("=", 1)
        table, own = f"wiggle::forceKernels_{name}(wiggle::ContactLaw)", f"wiggle::{NAMESPACE[name]}::"
        symbols = list(exported(obj))
        if table not in symbols:
            bad.append(f"{name}: its table function {table} is missing from {obj}")
        bad += [f"{name}: {s}" for s in symbols if s != table and own not in s and not s.startswith(DATA)]
    if bad:
        print("force kernel objects export symbols outside their instruction set's namespace:", *bad, sep="\n  ")
        return 1
    print(f"ok: {len(args)} variant objects export only their tables and their own namespace")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

#!/usr/bin/env python3
"""Checks PNG files for the tests: each decodes, has exactly WIDTH x HEIGHT pixels, and is not
blank (more than one distinct colour).

Usage: python3 check_png.py WIDTH HEIGHT FILE...
Exit codes: 0 all good, 1 a file failed (the reason is printed), 3 matplotlib missing.
"""
import sys

try:
    import matplotlib.image
    import numpy
except ImportError as error:
    print(f"matplotlib is not installed for {sys.executable} ({error})", file=sys.stderr)
    sys.exit(3)


def check(path, width, height):
    pixels = matplotlib.image.imread(path)  # rows x columns x channels
    if pixels.shape[1] != width or pixels.shape[0] != height:
        return f"{path}: {pixels.shape[1]} x {pixels.shape[0]} pixels, expected {width} x {height}"
    if not numpy.any(pixels != pixels[0, 0]):  # every pixel the colour of the first
        return f"{path}: blank (one colour)"
    return None


def main(argv):
    if len(argv) < 4:
        print(__doc__, file=sys.stderr)
        return 2
    width, height = int(argv[1]), int(argv[2])
    problems = [p for p in (check(f, width, height) for f in argv[3:]) if p]
    for p in problems:
        print(p, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

#!/usr/bin/env python3
"""Reads a golden rational CSV (scalecert golden's NAME.golden.rational.csv) into exact Fractions.

Each number is two integer columns, X_num and X_den; an empty pair is no value. Prints the pairs
asked (rho1, rho2), the exact verdict there and the exact squared distance or depth, one row a line
(the first ROWS rows when given).
Usage: tools/golden_rational.py NAME.golden.rational.csv [ROWS]
"""
import csv
import signal
import sys
from fractions import Fraction


def exact(row, name):
    """The column pair name_num / name_den as a Fraction, or None when empty."""
    num, den = row[name + "_num"], row[name + "_den"]
    return Fraction(int(num), int(den)) if num else None


def rows(path):
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            yield exact(row, "rho1"), exact(row, "rho2"), row["verdict"], exact(row, "squared")


if __name__ == "__main__":
    signal.signal(signal.SIGPIPE, signal.SIG_DFL)  # quietly, into `head`
    if len(sys.argv) not in (2, 3) or (len(sys.argv) == 3 and not sys.argv[2].isdigit()):
        sys.exit(__doc__.strip().splitlines()[-1])
    limit = int(sys.argv[2]) if len(sys.argv) == 3 else None
    for k, (rho1, rho2, verdict, squared) in enumerate(rows(sys.argv[1])):
        if k == limit:
            break
        print(rho1, rho2, verdict, "-" if squared is None else squared)

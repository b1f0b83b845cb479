"""python3 -m certify_kernel [reports/certificates.json] [--only ID ...] [--jobs N]

Re-checks every obligation of every certificate; prints one line per certificate and a
summary; exit 0 when nothing fails, 1 when an obligation, a sub-claim or its derivation fails,
2 on bad input.
"""
from __future__ import annotations

import argparse
import multiprocessing
import os
import sys
import time

from . import line, load, verify_certificate

DEFAULT = os.path.join("reports", "certificates.json")


def main(argv=None) -> int:
    """Parse the options, verify, print; the exit code."""
    parser = argparse.ArgumentParser(prog="python3 -m certify_kernel", description=__doc__.split("\n")[2])
    parser.add_argument("path", nargs="?", default=DEFAULT, help=f"the certificates file (default: {DEFAULT})")
    parser.add_argument("--only", nargs="+", metavar="ID", default=None, help="check only these certificates")
    parser.add_argument("--jobs", type=int, default=min(2, os.cpu_count() or 1), metavar="N",
                        help="processes (default: 2)")
    args = parser.parse_args(argv)
    try:
        data = load(args.path)
    except (OSError, ValueError) as exc:
        print(f"error: cannot read {args.path}: {exc}", file=sys.stderr)
        return 2
    certs = data["certificates"]
    if args.only:
        wanted = {i.upper() for i in args.only}
        unknown = wanted - {c["id"] for c in certs}
        if unknown:
            print(f"error: no certificate {', '.join(sorted(unknown))} in {args.path}", file=sys.stderr)
            return 2
        certs = [c for c in certs if c["id"] in wanted]
    start = time.perf_counter()
    if args.jobs > 1 and len(certs) > 1:
        heavy = sorted(range(len(certs)), key=lambda k: -len(str(certs[k]["obligations"])))
        with multiprocessing.get_context("fork" if hasattr(os, "fork") else "spawn").Pool(args.jobs) as pool:
            done = dict(zip(heavy, pool.map(verify_certificate, [certs[k] for k in heavy], chunksize=1)))
        results = [done[k] for k in range(len(certs))]
    else:
        results = [verify_certificate(c) for c in certs]
    for r in results:
        print(line(r))
    failed = [r["id"] for r in results if not r["ok"]]
    n = sum(r.get("subclaims", 0) for r in results)
    k, d = (sum(r.get(key, 0) for r in results) for key in ("verified", "derived"))
    whole = sum(1 for r in results if r["ok"] and r["subclaims"] and r["verified"] == r["subclaims"])
    proved = [r for r in results if r["ok"] and r["status"] in ("PASS", "ERRATUM")]
    pk, pn, pd = (sum(r[key] for r in proved) for key in ("verified", "subclaims", "derived"))
    print(f"{len(results)} certificates: {len(failed)} failed, {whole} independently verified whole; "
          f"{k}/{n} sub-claims independently verified ({d} with a derivation checked, {k - d} on obligations "
          f"only), {pk}/{pn} of the PASS and ERRATUM ones{f' ({100 * pk / pn:.0f}%)' if pn else ''}, "
          f"{pd} of them with a derivation checked ({time.perf_counter() - start:.1f} s)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

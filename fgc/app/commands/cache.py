"""``fgc cache info|clear``: the derivation and build cache ($FGC_CACHE_DIR)."""

from __future__ import annotations

import json

from fgc.app.commands.options import Formatter, verbosity_args
from fgc.app.commands.steps import EXIT_OK
from fgc.compiler import cache

NAME = "cache"
HELP = ("fgc's cache ($FGC_CACHE_DIR, default ~/.cache/fgc: derivations, native and "
        "HLS-stream builds): info or clear")


def add_parser(sub):
    p = sub.add_parser(NAME, help=HELP, description=f"fgc cache: {HELP}",
                       epilog="exit status: 0 success", formatter_class=Formatter)
    p.add_argument("action", choices=("info", "clear"),
                   help="info: directory, entries per kind, total size; clear: delete all of "
                        "them")
    p.add_argument("--json", action="store_true", dest="json_stdout",
                   help="info as JSON on stdout")
    verbosity_args(p, suppress=True)
    return p



def cmd_cache(args) -> int:
    if args.action == "clear":
        n = cache.clear()
        print(f"removed {n} entr{'y' if n == 1 else 'ies'} from {cache.cache_root()}")
        return EXIT_OK
    stats = cache.info()
    if args.json_stdout:
        print(json.dumps(stats, indent=2))
        return EXIT_OK
    print(f"cache dir: {stats['dir']}")
    for kind, n in stats["entries"].items():
        print(f"  {kind:<10} {n:>6} entries")
    print(f"total size: {stats['bytes'] / 1e6:.1f} MB ({stats['bytes']} bytes)")
    return EXIT_OK

"""``python -m certify COMMAND``: see :mod:`certify.cli`."""
from certify.cli import main

if __name__ == "__main__":
    raise SystemExit(main())

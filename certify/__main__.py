"""``python -m certify COMMAND``: see :mod:`certify.cli`."""
from certify.cli import run

if __name__ == "__main__":
    run()

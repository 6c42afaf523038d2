"""`-h` / `--help` for the bench scripts: prints the script's description (its docstring, with
its usage) and ends the script with exit status 0."""
import sys


def exit_on_help(doc):
    if any(a in ('-h', '--help') for a in sys.argv[1:]):
        print(doc.strip())
        sys.exit(0)

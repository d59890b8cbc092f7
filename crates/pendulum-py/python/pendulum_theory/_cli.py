"""The ``pendulum`` command, installed with the package as its console script.

It is the Rust command-line tool itself (``pendulum_cli::run``), linked
into the package's native module: the same parsing, output and exit
status as the binary built by ``cargo install``, from one build.
"""

import sys


def main() -> None:
    from pendulum_theory import _native

    # The command installs its own Ctrl-C handler (status 130, temporary
    # files removed); Python's would wait for the command to return.
    sys.exit(_native.cli(sys.argv))


if __name__ == "__main__":
    main()

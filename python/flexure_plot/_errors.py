"""The one error type of the plot module, importable without numpy or matplotlib (so that their
absence is reported as such, exit 4)."""


class PlotError(Exception):
    """A failure with the tool's exit code (docs/cli.md): 2 invalid input, 4 anything else."""

    def __init__(self, message, exit_code=2):
        super().__init__(message)
        self.exit_code = exit_code

"""The exceptions tether raises (the compiled module translates its C++ errors into these)."""


class TetherError(Exception):
    """Base class of tether's errors."""


class InputError(TetherError):
    """An error in the deck: ``file``, ``line`` (1-based, 0 when unknown) and ``message``."""

    def __init__(self, message, file="", line=0):
        self.message = message
        self.file = file
        self.line = line
        where = f"{file}:{line}" if line > 0 else file
        super().__init__(f"{where}: error: {message}" if where else message)


class ModelError(TetherError):
    """The model is valid input but cannot be solved as posed (singular, unsupported combination)."""

    def __init__(self, message):
        self.message = message
        super().__init__(message)


class SolverError(TetherError):
    """The analysis could not be completed (Job.run(check=True)) or a linear solve failed."""

    def __init__(self, message):
        self.message = message
        super().__init__(message)


class ResourceError(TetherError):
    """The machine refused something the run needs (a scratch directory, disk space)."""

    def __init__(self, message):
        self.message = message
        super().__init__(message)


class DeckWarning(UserWarning):
    """Something the deck reader accepted but ignored or reinterpreted."""

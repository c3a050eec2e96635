"""Diagnostics in the form compilers and editors understand: file:line:col: error: message."""


class StError(Exception):
    """One refusal: where it is and why."""

    def __init__(self, file, line, col, message):
        super().__init__(message)
        self.file = file
        self.line = line
        self.col = col
        self.message = message

    def __str__(self):
        return f"{self.file}:{self.line}:{self.col}: error: {self.message}"

    def __reduce__(self):  # pickled with its place (a library's checked state holds its refusals)
        return type(self), (self.file, self.line, self.col, self.message), self.__dict__


class StWarning(StError):
    """One construct taken as the vendors take it, with their warning (an implicit narrowing): shown, not refused."""

    def __str__(self):
        return f"{self.file}:{self.line}:{self.col}: warning: {self.message}"


class StErrors(Exception):
    """Every refusal found in a run, in source order."""

    def __init__(self, errors):
        super().__init__("\n".join(str(e) for e in errors))
        self.errors = list(errors)

    def __reduce__(self):
        return type(self), (self.errors,), self.__dict__

"""The one error the export reports: a source it cannot export faithfully, named by file."""


class ExportError(Exception):
    def __init__(self, where, message):
        super().__init__(f"{where}: {message}")
        self.where = where
        self.message = message

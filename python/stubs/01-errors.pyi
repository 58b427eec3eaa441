# ---- errors ------------------------------------------------------------------------------------------
class Error(Exception): ...
class ModelError(Error, ValueError):
    """'file:line: key: what is wrong; expected ...' — the CLI's text after 'error: '."""
class InvalidArgument(Error, ValueError):
    parameter: str
class NumericalError(Error, RuntimeError): ...
class NetworkError(Error, ValueError):
    column: int


"""turf.TurfError: an input turf refused, named as turf-sim names it (core/errors.h)."""


class TurfError(ValueError):
    """A refused input. ``error`` is the error's name ("not_finite", "out_of_range", "unknown_robot", ...:
    the names of turf-sim's control replies and refusal counters); ``reason`` says which input and why.
    The simulation is as it was before the call."""

    def __init__(self, error, reason=""):
        super().__init__(reason or error)
        self.error = error
        self.reason = reason

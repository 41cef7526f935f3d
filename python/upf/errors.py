"""upf's errors as Python exceptions.

A bad scene raises SceneError (a ValueError) listing every problem as (where, message): the JSON
path or file, and what is wrong with it. An instability raises InstabilityError with the step,
the particle id and the quantity that went bad. A view used after the world moved its arrays
raises StaleViewError.
"""


class SceneError(ValueError):
    """A scene (file or dict) that upf refuses; .problems is a list of (where, message)."""

    def __init__(self, message, problems=()):
        super().__init__(message)
        self.problems = list(problems)


class InstabilityError(RuntimeError):
    """The simulation blew up: .step, .time, .particle_id, .quantity, .value, .limit."""

    def __init__(self, message, step=0, time=0.0, particle_id=0, quantity="", value=0.0,
                 limit=0.0):
        super().__init__(message)
        self.step = step
        self.time = time
        self.particle_id = particle_id
        self.quantity = quantity
        self.value = value
        self.limit = limit


class StaleViewError(RuntimeError):
    """A particle view used after the world stepped, reordered or restored its arrays."""

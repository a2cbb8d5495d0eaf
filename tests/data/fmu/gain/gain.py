"""A gain, y = k u, as a Python FMU (FMI 2 co-simulation) built by ``pythonfmu build`` at test time
(tests/support/fmus.py): the Python kind of FMU hlacore.fmu runs beside the ones compiled from C."""

from pythonfmu import Fmi2Causality, Fmi2Slave, Fmi2Variability, Real


class Gain(Fmi2Slave):
    """y = k u, computed at each step from the input held over it."""

    author = "hlacore"
    description = "y = k u (hlacore's tests)"

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self.u = 0.0
        self.k = 2.0
        self.y = 0.0
        self.register_variable(Real("u", causality=Fmi2Causality.input))
        self.register_variable(Real("k", causality=Fmi2Causality.parameter, variability=Fmi2Variability.tunable))
        self.register_variable(Real("y", causality=Fmi2Causality.output))

    def do_step(self, current_time, step_size):
        self.y = self.k * self.u
        return True

"""Integer, Boolean and String through the federation, as a Python FMU (FMI 2 co-simulation) built by
``pythonfmu build`` at test time (tests/support/fmus.py): at each step twice = 2 n, negated = not flag and
shout = the word in capitals with "!", from the inputs held over the step."""

from pythonfmu import Boolean, Fmi2Causality, Fmi2Slave, Integer, String


class Typed(Fmi2Slave):
    """One input and one output of each of the three types."""

    author = "hlacore"
    description = "Integer, Boolean and String (hlacore's tests)"

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self.n, self.flag, self.word = 0, False, ""
        self.twice, self.negated, self.shout = 0, True, "!"
        for variable in (Integer("n", causality=Fmi2Causality.input), Boolean("flag", causality=Fmi2Causality.input),
                         String("word", causality=Fmi2Causality.input),
                         Integer("twice", causality=Fmi2Causality.output),
                         Boolean("negated", causality=Fmi2Causality.output),
                         String("shout", causality=Fmi2Causality.output)):
            self.register_variable(variable)

    def do_step(self, current_time, step_size):
        self.twice, self.negated, self.shout = 2 * self.n, not self.flag, self.word.upper() + "!"
        return True

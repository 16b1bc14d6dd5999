"""A deliberately wrong outside solver: numpy_stepper.py with every collision impulse applied
twice. The suite must fail it (docs/your-solver.md, "The examples that ship"): the energy grows
at every collision (energy_drift), and the trajectories leave the exact ones by the same amount
at every dt (trajectory_error, and a work-precision line that does not fall with dt).
"""

from numpy_stepper import NumPyStepper


class ImpulseTwice(NumPyStepper):
    version = "numpy-wrong 1 (impulse applied twice)"

    def impulse(self, un, wsum):
        return 2 * super().impulse(un, wsum)

from enum import StrEnum

class OutputKind(StrEnum):
    CONDITION = "condition"
    DRIVING = "driving"
    ENERGY = "energy"
    KINEMATICS = "kinematics"
    POINTS = "points"
    REACTIONS = "reactions"
    REDUCED = "reduced"
    SHAKING = "shaking"

    def __str__(self) -> str:
        return str(self.value)

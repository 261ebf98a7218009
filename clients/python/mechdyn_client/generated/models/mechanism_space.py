from enum import StrEnum

class MechanismSpace(StrEnum):
    PLANAR = "planar"
    SPATIAL = "spatial"

    def __str__(self) -> str:
        return str(self.value)

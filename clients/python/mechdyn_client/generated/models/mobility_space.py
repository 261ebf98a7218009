from enum import StrEnum

class MobilitySpace(StrEnum):
    PLANAR = "planar"
    SPATIAL = "spatial"

    def __str__(self) -> str:
        return str(self.value)

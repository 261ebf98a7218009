from enum import StrEnum

class JobMobilityKind(StrEnum):
    MOBILITY = "mobility"

    def __str__(self) -> str:
        return str(self.value)

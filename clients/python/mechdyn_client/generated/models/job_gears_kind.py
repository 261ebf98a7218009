from enum import StrEnum

class JobGearsKind(StrEnum):
    GEARS = "gears"

    def __str__(self) -> str:
        return str(self.value)

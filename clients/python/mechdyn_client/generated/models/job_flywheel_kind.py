from enum import StrEnum

class JobFlywheelKind(StrEnum):
    FLYWHEEL = "flywheel"

    def __str__(self) -> str:
        return str(self.value)

from enum import StrEnum

class LoadType(StrEnum):
    DAMPER = "damper"
    FORCE = "force"
    SPRING = "spring"
    TORQUE = "torque"

    def __str__(self) -> str:
        return str(self.value)

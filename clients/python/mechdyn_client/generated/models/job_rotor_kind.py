from enum import StrEnum

class JobRotorKind(StrEnum):
    ROTOR = "rotor"

    def __str__(self) -> str:
        return str(self.value)

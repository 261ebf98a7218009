from enum import StrEnum

class JobDynamicsKind(StrEnum):
    DYNAMICS = "dynamics"

    def __str__(self) -> str:
        return str(self.value)

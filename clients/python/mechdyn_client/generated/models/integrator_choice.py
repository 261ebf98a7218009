from enum import StrEnum

class IntegratorChoice(StrEnum):
    AUTO = "auto"
    DOP853 = "dop853"
    DOPRI5 = "dopri5"
    RADAU5 = "radau5"

    def __str__(self) -> str:
        return str(self.value)

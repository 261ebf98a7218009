from enum import StrEnum

class JobKinetostaticsKind(StrEnum):
    KINETOSTATICS = "kinetostatics"

    def __str__(self) -> str:
        return str(self.value)

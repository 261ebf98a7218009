from enum import StrEnum

class JobCamsKind(StrEnum):
    CAMS = "cams"

    def __str__(self) -> str:
        return str(self.value)

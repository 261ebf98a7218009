from enum import StrEnum

class JobCheckKind(StrEnum):
    CHECK = "check"

    def __str__(self) -> str:
        return str(self.value)

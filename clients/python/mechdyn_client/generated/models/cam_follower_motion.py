from enum import StrEnum

class CamFollowerMotion(StrEnum):
    OSCILLATING = "oscillating"
    TRANSLATING = "translating"

    def __str__(self) -> str:
        return str(self.value)

from enum import StrEnum

class CamFollowerType(StrEnum):
    FLAT = "flat"
    KNIFE = "knife"
    ROLLER = "roller"

    def __str__(self) -> str:
        return str(self.value)

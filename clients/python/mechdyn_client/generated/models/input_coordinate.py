from enum import StrEnum

class InputCoordinate(StrEnum):
    ROTATION = "rotation"
    SLIDE = "slide"

    def __str__(self) -> str:
        return str(self.value)

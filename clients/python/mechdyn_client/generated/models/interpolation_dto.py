from enum import StrEnum

class InterpolationDto(StrEnum):
    LINEAR = "linear"
    SPLINE = "spline"
    STEP = "step"

    def __str__(self) -> str:
        return str(self.value)

from enum import StrEnum

class CheckFormat(StrEnum):
    GRADESCOPE = "gradescope"
    MECHDYN = "mechdyn"
    PRAIRIELEARN = "prairielearn"

    def __str__(self) -> str:
        return str(self.value)

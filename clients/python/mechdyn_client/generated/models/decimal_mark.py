from enum import StrEnum

class DecimalMark(StrEnum):
    COMMA = "comma"
    POINT = "point"

    def __str__(self) -> str:
        return str(self.value)

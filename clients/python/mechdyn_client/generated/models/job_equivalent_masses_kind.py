from enum import StrEnum

class JobEquivalentMassesKind(StrEnum):
    EQUIVALENT_MASSES = "equivalent_masses"

    def __str__(self) -> str:
        return str(self.value)

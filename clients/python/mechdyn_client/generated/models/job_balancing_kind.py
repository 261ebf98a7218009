from enum import StrEnum

class JobBalancingKind(StrEnum):
    BALANCING = "balancing"

    def __str__(self) -> str:
        return str(self.value)

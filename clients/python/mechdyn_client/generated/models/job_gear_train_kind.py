from enum import StrEnum

class JobGearTrainKind(StrEnum):
    GEAR_TRAIN = "gear_train"

    def __str__(self) -> str:
        return str(self.value)

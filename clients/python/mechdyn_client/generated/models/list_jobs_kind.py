from enum import StrEnum

class ListJobsKind(StrEnum):
    BALANCING = "balancing"
    CAMS = "cams"
    CHECK = "check"
    DYNAMICS = "dynamics"
    EQUIVALENT_MASSES = "equivalent_masses"
    FLYWHEEL = "flywheel"
    GEARS = "gears"
    GEAR_TRAIN = "gear_train"
    KINETOSTATICS = "kinetostatics"
    MOBILITY = "mobility"
    ROTOR = "rotor"

    def __str__(self) -> str:
        return str(self.value)

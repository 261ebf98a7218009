from enum import StrEnum

class JointType(StrEnum):
    CONTACT = "contact"
    GEAR = "gear"
    PIN_SLOT = "pin_slot"
    PRISMATIC = "prismatic"
    REVOLUTE = "revolute"

    def __str__(self) -> str:
        return str(self.value)

from enum import StrEnum

class JointType(StrEnum):
    CONTACT = "contact"
    CYLINDRICAL = "cylindrical"
    GEAR = "gear"
    PIN_SLOT = "pin_slot"
    PRISMATIC = "prismatic"
    REVOLUTE = "revolute"
    SPHERE_IN_CYLINDER = "sphere_in_cylinder"
    SPHERICAL = "spherical"
    UNIVERSAL = "universal"

    def __str__(self) -> str:
        return str(self.value)

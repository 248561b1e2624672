"""swarmagg.State: the controller states, named as the library names them."""

import enum

from ._core import AGENT_STATES

State = enum.IntEnum("State", AGENT_STATES, module=__name__)
State.__doc__ = (
    "Controller state of an agent: the values in Simulation.states (int8). "
    "GO searches, WAIT is aggregated, LEAVE walks away, APPROACH (Soysal) heads for an agent."
)

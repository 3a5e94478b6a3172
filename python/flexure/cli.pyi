# Type stubs of flexure.cli (docs/python.md "Command functions"): the command functions, the same
# objects as the package's top-level names of the same name.
from . import bench as bench
from . import beam as beam
from . import cfm as cfm
from . import design as design
from . import dynamics as dynamics
from . import map as map
from . import materials as materials
from . import mechanism as mechanism
from . import path as path
from . import prbm as prbm
from . import read as read
from . import sweep as sweep
from . import validate as validate

__all__: list[str]

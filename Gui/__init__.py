"""HoleFill's FreeCAD Gui layer (installed as the package HoleFillGui): commands,
task panels, view providers. Imported lazily by InitGui.py."""
import os

_HERE = os.path.dirname(os.path.abspath(__file__))


class SelectionError(Exception):
    """A selection a command cannot work on; the message says what to select instead. Raised by
    every panel and overlay, caught once per command (commands.py), shown as a message."""


def icon(name):
    """Path of an icon shipped in Resources/icons/ of the assembled addon."""
    return os.path.join(os.path.dirname(_HERE), "Resources", "icons", name)

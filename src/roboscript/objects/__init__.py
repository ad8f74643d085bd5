"""The object library: every object type's shape (as primitive parts), size, colour, category and mass.

Prior knowledge, not simulation: the simulator builds bodies from it, perception reads containers' interiors from
it, and a real robot's perception would use the same descriptions.
"""

from roboscript.objects.library import ObjectType, get_object_type, object_types

__all__ = ["ObjectType", "get_object_type", "object_types"]

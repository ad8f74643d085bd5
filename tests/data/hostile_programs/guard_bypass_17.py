# class: guard_bypass
# expect: refused
# attack: class hooks named outright (__init_subclass__, __set_name__, __class_getitem__, __getattr__, __slots__, __del__), and a class-body function named staticmethod/property used as a decorator on __repr__, so that the decorator is the program's own function
class H:
    def __init_subclass__(cls):
        pass
    def __set_name__(self, owner, name):
        pass
    def __class_getitem__(cls, item):
        return item
    __slots__ = ('a',)

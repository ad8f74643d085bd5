# class: format_walk
# expect: refused
# attack: the checked .format rewrite against classes: a method named format called on an instance and on its class, a str subclass (base str, a class of that name defined in a function never run) whose template passes the check while its own format method reads attributes by other means, and a class attribute holding str.format
def never():
    class str:
        pass
class T(str):
    def format(self, *args):
        return 'mine'
class W:
    def format(self, value):
        return 'W' + repr(value)
u = '_' + '_'
walk = '{0.' + u + 'class' + u + '}'
results = []
for attempt in (
    lambda: W().format(1),
    lambda: W.format(W(), 2),
    lambda: T(walk).format(1),
    lambda: T('{0}').format(np),
    lambda: T.format(walk, 1),
    lambda: str.format(T('{0.real}'), 1),
    lambda: '{0[x]}'.format({'x': 1}),
):
    try:
        results.append(repr(attempt())[:60])
    except Exception as exc:
        results.append('refused: ' + str(exc)[:70])
print(results)

# class: unbounded_trusted_work
# expect: contained
# attack: a 2**30-leaf list made of shared references (tiny when pickled) as an object name: the tools' side repr()s it into its error message, gigabytes in one C call
names = get_object_name_list()
leaf = [names[0]]
for level in range(30):
    leaf = [leaf, leaf]
try:
    get_object_pose(leaf)
except Exception as exc:
    print("refused:", str(exc)[:200])

# class: lazy_iterator
# expect: contained
# attack: a map whose first item is sum(range(10**15)), passed as a list of names: the tools' side computes it in C, where no timer signal reaches, when it checks the names
print(get_object_name_list())
detect_objects(map(sum, [range(10 ** 15)]))
print("detected")

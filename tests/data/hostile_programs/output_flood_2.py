# class: output_flood
# expect: contained
# attack: small arguments (a list of 60000 references to one 1000-character name and a number) make the tools' side build a 60 MB error message, which is sent back and re-raised as the program's error
names = get_object_name_list()
filler = "y" * 1000
detect_objects([filler] * 60000 + [0])

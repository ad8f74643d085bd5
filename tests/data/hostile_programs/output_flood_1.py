# class: output_flood
# expect: contained
# attack: ends with an exception whose message is 60 million characters, so the error string of the result (not only the printed output) is huge
objects = get_object_name_list()
raise ValueError("could not place " + "the apple, " * 5_500_000)

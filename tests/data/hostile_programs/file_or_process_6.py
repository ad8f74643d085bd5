# class: file_or_process
# expect: contained
# attack: gets the interpreter to import on the program's behalf with no import statement and no dunder: str.encode, bytes.decode and str(b, encoding) with a codec not yet loaded make the codec registry's search function (encodings, real builtins) call __import__('encodings.<name>'), which looks for files; the guard and the restricted builtins do not see it, only the seccomp filter stops it
names = get_object_name_list()
for codec in ("cp437", "utf-7", "idna", "punycode", "mac_roman", "koi8_r", "utf_8_sig"):
    try:
        print(codec, "apple".encode(codec))
    except Exception as exc:
        print(codec, "refused:", str(exc)[:80])
print(str(b"MARK", "cp1252"))
print("ran on after the imports")

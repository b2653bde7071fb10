# The cabinet image's partition GUIDs and names (scripts/image.sh and
# debian/image/customize.sh). Fixed, so the same inputs make the same image
# and the boot entry can name the root by PARTUUID.
DISK_UUID=8d1a0a9e-7a4f-4b0e-9d4c-61726361640a
ESP_UUID=8d1a0a9e-7a4f-4b0e-9d4c-61726361640b
ROOT_UUID=8d1a0a9e-7a4f-4b0e-9d4c-61726361640c
STATE_UUID=8d1a0a9e-7a4f-4b0e-9d4c-61726361640d

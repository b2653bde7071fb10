#!/bin/sh
# mmdebstrap's customize hook for the cabinet image (scripts/image.sh):
# turns the installed Debian 12 system into an appliance with a read-only
# root. $1: the root tree. Every choice is explained in docs/packaging.md.
set -eu
R=$1
H=$(dirname "$0")

# Mounts: the root read-only; the state partition on /var/lib/arcaded
# (checked by systemd-fsck at every boot, which replays its journal, and
# grown after systemd-repart grew the partition); tmpfs where a running
# system writes.
. "$H/ids.sh"
cat > "$R/etc/fstab" <<FSTAB
# The cabinet image (docs/packaging.md). The root is never written.
PARTUUID=$ROOT_UUID  /                 ext4   ro,noatime                                      0 0
PARTUUID=$STATE_UUID /var/lib/arcaded  ext4   rw,noatime,nosuid,nodev,noexec,x-systemd.growfs,x-systemd.after=systemd-repart.service 0 2
tmpfs                /tmp              tmpfs  mode=1777,nosuid,nodev,size=64M                  0 0
tmpfs                /var/tmp          tmpfs  mode=1777,nosuid,nodev,size=16M                  0 0
tmpfs                /var/log          tmpfs  mode=0755,nosuid,nodev,noexec,size=16M           0 0
FSTAB

# The state partition is the disk's last: grown to the end of the disk at
# the first boot (systemd-repart; x-systemd.growfs above grows the file
# system to it).
mkdir -p "$R/etc/repart.d"
cat > "$R/etc/repart.d/50-arcaded-state.conf" <<REPART
[Partition]
Type=linux-generic
REPART

# Logs in memory only, capped: nothing but the game's own state is written
# to the card.
mkdir -p "$R/etc/systemd/journald.conf.d"
cat > "$R/etc/systemd/journald.conf.d/50-arcaded-image.conf" <<JOURNAL
[Journal]
Storage=volatile
RuntimeMaxUse=16M
JOURNAL

# No login on the screen: getty on tty1 masked; logind (which would start
# gettys on other consoles, and needs D-Bus, not installed) masked too, and
# Debian's getty-static (gettys on tty2-6 when logind is missing).
# The random seed cannot be saved on a read-only root: its service masked
# (the kernel seeds its generator itself).
# Timers that would write to the read-only root or reach for the network
# (apt's daily runs, dpkg's database backup, LVM scrubbing) are masked.
for u in getty@tty1.service getty-static.service systemd-logind.service systemd-random-seed.service \
	apt-daily.timer apt-daily-upgrade.timer dpkg-db-backup.timer e2scrub_all.timer \
	e2scrub_reap.service; do
	ln -sf /dev/null "$R/etc/systemd/system/$u"
done
rm -f "$R/etc/systemd/system/timers.target.wants/apt-daily.timer" \
	"$R/etc/systemd/system/timers.target.wants/apt-daily-upgrade.timer" \
	"$R/etc/systemd/system/timers.target.wants/dpkg-db-backup.timer" \
	"$R/etc/systemd/system/timers.target.wants/e2scrub_all.timer" \
	"$R/etc/systemd/system/multi-user.target.wants/e2scrub_reap.service"

# No network service: none is installed but systemd-networkd, which stays
# disabled unless the image is built with systemd-networkd .network files
# in debian/image/network/ (then they are installed and it is enabled).
if ls "$H"/network/*.network > /dev/null 2>&1; then
	mkdir -p "$R/etc/systemd/network"
	cp "$H"/network/*.network "$R/etc/systemd/network/"
	chroot "$R" systemctl enable systemd-networkd.service
fi

# Services of what a cabinet does not do: logins (utmp records, the
# nologin file), a persistent journal to flush to, crash records in EFI
# variables (pstore). Every started program costs on a small CPU.
for u in systemd-update-utmp.service systemd-update-utmp-runlevel.service \
	systemd-user-sessions.service systemd-journal-flush.service systemd-pstore.service; do
	ln -sf /dev/null "$R/etc/systemd/system/$u"
done
# Kernel modules udev would load for what a cabinet does not use: running
# virtual machines, the PC speaker, floppy drives.
mkdir -p "$R/etc/modprobe.d"
printf 'blacklist %s\n' kvm kvm_intel kvm_amd pcspkr floppy > "$R/etc/modprobe.d/arcaded-image.conf"

# Generators of what a cabinet does not have (SysV scripts, rc.local,
# encrypted or verity volumes, hibernation, offline updates, partitions
# found by type, gettys on serial and hypervisor consoles): seconds of
# every boot on a small CPU. fstab's stays.
mkdir -p "$R/etc/systemd/system-generators"
for g in systemd-sysv-generator systemd-rc-local-generator systemd-cryptsetup-generator \
	systemd-integritysetup-generator systemd-veritysetup-generator \
	systemd-hibernate-resume-generator systemd-system-update-generator \
	systemd-gpt-auto-generator systemd-getty-generator; do
	ln -sf /dev/null "$R/etc/systemd/system-generators/$g"
done

# An empty machine-id: systemd makes a new one in memory at every boot
# (the root is read-only), and no boot counts as a first boot.
: > "$R/etc/machine-id"
echo cabinet > "$R/etc/hostname"
printf '127.0.0.1\tlocalhost\n127.0.1.1\tcabinet\n' > "$R/etc/hosts"

# /etc and /var up to date for ConditionNeedsUpdate=: ldconfig, sysusers,
# hwdb and catalog updates do not run at boot.
touch "$R/etc/.updated" "$R/var/.updated"
